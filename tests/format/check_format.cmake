cmake_minimum_required(VERSION 3.25)
# Fails when a tracked .cpp/.h file differs from what clang-format (the repository's
# .clang-format) makes of it, and names the files. Skips (exit 77) without clang-format or
# outside a git checkout.
# Run: cmake -DSOURCE_DIR=<repo> -P check_format.cmake
find_program(CLANG_FORMAT NAMES clang-format clang-format-14)
find_program(GIT git)
if(NOT CLANG_FORMAT OR NOT GIT)
    message("SKIP: clang-format or git not found")
    cmake_language(EXIT 77)
endif()
execute_process(COMMAND ${GIT} ls-files -- "*.cpp" "*.h"
                WORKING_DIRECTORY ${SOURCE_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE listed ERROR_QUIET)
if(NOT rc EQUAL 0)
    message("SKIP: ${SOURCE_DIR} is not a git checkout")
    cmake_language(EXIT 77)
endif()
string(REPLACE "\n" ";" files "${listed}")
list(FILTER files EXCLUDE REGEX "^$")
list(LENGTH files count)
# One clang-format for all files; it names every file that differs in its diagnostics.
execute_process(COMMAND ${CLANG_FORMAT} --dry-run -Werror ${files}
                WORKING_DIRECTORY ${SOURCE_DIR}
                RESULT_VARIABLE frc OUTPUT_QUIET ERROR_VARIABLE diagnostics)
if(NOT frc EQUAL 0)
    string(REGEX MATCHALL "[^\n:]+\\.(cpp|h):[0-9]+:[0-9]+: error" hits "${diagnostics}")
    set(unformatted "")
    foreach(hit IN LISTS hits)
        string(REGEX REPLACE ":[0-9]+:[0-9]+: error$" "" file "${hit}")
        list(APPEND unformatted ${file})
    endforeach()
    list(REMOVE_DUPLICATES unformatted)
    foreach(file IN LISTS unformatted)
        message(STATUS "not formatted: ${file}")
    endforeach()
    list(LENGTH unformatted n)
    message(FATAL_ERROR "${n} of ${count} files need clang-format -i (listed above)")
endif()
message(STATUS "format: ${count} files as clang-format makes them")
