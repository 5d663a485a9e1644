# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# Per-generator CPack settings (CPACK_PROJECT_CONFIG_FILE): the Debian package installs the
# relocatable tree in /opt/mmrep; the .tar.gz has it at its root.
if(CPACK_GENERATOR STREQUAL "DEB")
  set(CPACK_PACKAGING_INSTALL_PREFIX /opt/mmrep)
endif()
