# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# mmrep_embed_text(<target-var> INPUT <file> SYMBOL <name>)
#   Adds a generated source to <target-var> that defines `const char <name>[]` = file contents.
#   SLICER_MODULE: also exported as Slicer's `XMLModuleDescription` / `GetXMLModuleDescription()`.
function(mmrep_embed_text out_var)
  cmake_parse_arguments(E "SLICER_MODULE" "INPUT;SYMBOL" "" ${ARGN})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${E_SYMBOL}.cxx)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${E_INPUT} -DOUTPUT=${out} -DSYMBOL=${E_SYMBOL} -DSLICER_MODULE=${E_SLICER_MODULE}
            -P ${PROJECT_SOURCE_DIR}/Utilities/CMake/EmbedText.cmake
    DEPENDS ${E_INPUT} ${PROJECT_SOURCE_DIR}/Utilities/CMake/EmbedText.cmake
    COMMENT "Embedding ${E_INPUT}")
  set(${out_var} ${${out_var}} ${out} PARENT_SCOPE)
endfunction()

# mmrep_add_cli_module(<Name> [TEST_ONLY] [SOURCES extra.cxx ...] [LIBRARIES lib ...])
#   Slicer CLI module in the current folder, from <Name>.xml and <Name>.cxx, written once for the
#   stand-alone and the Slicer extension build (the folders come from the top-level CMakeLists):
#   - <Name>Lib: shared library exporting Slicer's contract `XMLModuleDescription`,
#     `GetXMLModuleDescription()` and `int ModuleEntryPoint(int, char*[])`, in ${MMREP_CLI_LIBRARY_DIR};
#   - <Name>: executable in ${MMREP_CLI_RUNTIME_DIR} that just calls ModuleEntryPoint;
#   - install rules for both (RPATH relative to the installed executable);
#   - ctest `<Name>.XmlValidatesAgainstSchema`: `<Name> --xml` passes xmllint --schema;
#   - the folder's Testing/ subdirectory, when present and BUILD_TESTING is on.
#   TEST_ONLY: a module for the tests, neither installed nor listed in the global property
#   MMREP_CLI_MODULES (the product's modules).
function(mmrep_add_cli_module name)
  cmake_parse_arguments(M "TEST_ONLY" "" "SOURCES;LIBRARIES" ${ARGN})
  set(xml ${CMAKE_CURRENT_SOURCE_DIR}/${name}.xml)
  set(sources ${name}.cxx ${M_SOURCES})
  mmrep_embed_text(sources INPUT ${xml} SYMBOL ${name}XML SLICER_MODULE)
  add_library(${name}Lib SHARED ${sources})
  target_link_libraries(${name}Lib PRIVATE MMRepCLI ${M_LIBRARIES})
  target_compile_definitions(${name}Lib PRIVATE MMREP_MODULE_NAME="${name}")
  set_target_properties(${name}Lib PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/${MMREP_CLI_LIBRARY_DIR})
  add_executable(${name} ${PROJECT_SOURCE_DIR}/Libs/MMRepCLI/mmrepModuleMain.cxx)
  target_link_libraries(${name} PRIVATE ${name}Lib)
  file(RELATIVE_PATH rpath /${MMREP_INSTALL_CLI_RUNTIME_DIR} /${MMREP_INSTALL_CLI_LIBRARY_DIR})
  set_target_properties(${name} PROPERTIES
    RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/${MMREP_CLI_RUNTIME_DIR}
    BUILD_RPATH "${PROJECT_BINARY_DIR}/${MMREP_CLI_LIBRARY_DIR}"
    INSTALL_RPATH "$ORIGIN/${rpath}")
  if(NOT M_TEST_ONLY)
    set_property(GLOBAL APPEND PROPERTY MMREP_CLI_MODULES ${name})
    install(TARGETS ${name} RUNTIME DESTINATION ${MMREP_INSTALL_CLI_RUNTIME_DIR} COMPONENT RuntimeLibraries)
    install(TARGETS ${name}Lib LIBRARY DESTINATION ${MMREP_INSTALL_CLI_LIBRARY_DIR} COMPONENT RuntimeLibraries)
  endif()
  if(NOT BUILD_TESTING)
    return()
  endif()
  if(XMLLINT_EXECUTABLE)
    add_test(NAME ${name}.XmlValidatesAgainstSchema
      COMMAND sh -c "set -e; '$<TARGET_FILE:${name}>' --xml > '${CMAKE_CURRENT_BINARY_DIR}/${name}.xml.out'; cmp '${CMAKE_CURRENT_BINARY_DIR}/${name}.xml.out' '${xml}'; '${XMLLINT_EXECUTABLE}' --noout --schema '${MMREP_MODULE_SCHEMA}' '${CMAKE_CURRENT_BINARY_DIR}/${name}.xml.out'")
  endif()
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/Testing/CMakeLists.txt)
    add_subdirectory(Testing)
  endif()
endfunction()

# mmrep_add_gtest(<Name> SOURCES a.cxx ... LIBRARIES ...)
#   A GoogleTest executable whose tests each become a ctest test (discovered before running).
function(mmrep_add_gtest name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBRARIES} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    MMREP_SOURCE_DIR="${PROJECT_SOURCE_DIR}" MMREP_BINARY_DIR="${PROJECT_BINARY_DIR}"
    MMREP_SAMPLE_DATA="${MMREP_SAMPLE_DATA}" MMREP_TEST_DATA="${MMREP_TEST_DATA}")
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/Testing/Utilities)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  # NO_PRETTY_VALUES: names from the cases' own name generators, not "# GetParam() = <bytes>".
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST NO_PRETTY_VALUES NO_PRETTY_TYPES
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} PROPERTIES TIMEOUT 600)
endfunction()
