# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# cmake -DINPUT=file.xml -DOUTPUT=out.cxx -DSYMBOL=Name [-DSLICER_MODULE=ON] -P EmbedText.cmake
# Writes a C++ source defining `extern const char SYMBOL[]` holding the file's exact bytes,
# so a module's .xml is compiled in (single source of truth, no run-time file lookup).
# SLICER_MODULE: the bytes are Slicer's shared-library contract instead, the exported C symbol
# `XMLModuleDescription` and the function `GetXMLModuleDescription()` (Slicer's CLI factory looks
# for either beside ModuleEntryPoint), SYMBOL being an alias of the same bytes.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" length)
math(EXPR length "${length} / 2 + 1")
# Character literals ('\xe2') are valid chars for every byte, also non-ASCII ones (UTF-8 text).
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(('[^']+',){16})" "\\1\n" bytes "${bytes}")
if(SLICER_MODULE)
  set(export "__attribute__((visibility(\"default\")))")
  file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT}; do not edit.
extern \"C\" {
${export} extern const char XMLModuleDescription[${length}];
const char XMLModuleDescription[${length}] = {
${bytes}0};
${export} char* GetXMLModuleDescription() { return const_cast<char*>(XMLModuleDescription); }
}
extern const char ${SYMBOL}[${length}] __attribute__((alias(\"XMLModuleDescription\")));
")
else()
  file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT}; do not edit.\nextern const char ${SYMBOL}[];\nconst char ${SYMBOL}[] = {\n${bytes}0};\n")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
