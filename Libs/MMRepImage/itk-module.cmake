# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# ITK module description (as ITK remote modules declare theirs): the two image filters of MMRep's image
# stage, header-only, depending on ITK's core only. The tests also use ITK's readers and distance maps.
get_filename_component(MY_CURRENT_DIR "${CMAKE_CURRENT_LIST_FILE}" PATH)
file(READ "${MY_CURRENT_DIR}/README.md" DOCUMENTATION)
itk_module(MMRepImage
  DEPENDS
    ITKCommon
    ITKMesh
  TEST_DEPENDS
    ITKTestKernel
    ITKGoogleTest
    ITKIONRRD
    ITKDistanceMap
    ITKThresholding
  DESCRIPTION "${DOCUMENTATION}"
  EXCLUDE_FROM_DEFAULT
)
