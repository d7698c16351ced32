# Writes OUTPUT (buildcommit.h) with the git commit of SOURCE_DIR for the About box; run at every
# build, the file changes (and mainwindow_help.cpp recompiles) only when the commit does. Outside
# a git checkout (a source tarball) the commit is "unknown".
execute_process(COMMAND git rev-parse --short=12 HEAD
    WORKING_DIRECTORY ${SOURCE_DIR}
    OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR commit STREQUAL "")
    set(commit "unknown")
endif()
set(content "#pragma once\n#define DRIVEBENCH_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
    file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL content)
    file(WRITE ${OUTPUT} "${content}")
endif()
