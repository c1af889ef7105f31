# cmake -DTOFSIM=<tofsim> -DVERSION=<project version> -P check_version.cmake:
# `tofsim --version` prints the CMake project's version, and nothing else.
execute_process(COMMAND ${TOFSIM} --version OUTPUT_VARIABLE out RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0 OR NOT out STREQUAL "tofsim ${VERSION}")
  message(FATAL_ERROR "tofsim --version: '${out}' (exit ${rc}), expected 'tofsim ${VERSION}'")
endif()
message(STATUS "${out}")
