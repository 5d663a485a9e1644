# cmake -DINPUT=file.xml -DOUTPUT=out.cxx -DSYMBOL=Name -P EmbedText.cmake
# Writes a C++ source defining `extern const char SYMBOL[]` holding the file's exact bytes,
# so a module's .xml is compiled in (single source of truth, no run-time file lookup).
file(READ "${INPUT}" hex HEX)
# Character literals ('\xe2') are valid chars for every byte, also non-ASCII ones (UTF-8 text).
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(('[^']+',){16})" "\\1\n" bytes "${bytes}")
file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT}; do not edit.\nextern const char ${SYMBOL}[];\nconst char ${SYMBOL}[] = {\n${bytes}0};\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
