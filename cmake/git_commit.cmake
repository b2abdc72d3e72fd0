# Writes OUT, a header that defines SOFTRASTER_GIT_COMMIT as the commit of the source tree
# SRC ("unknown" outside a git checkout, "-dirty" after it when files differ from it); run
# at every build, it rewrites the header only when that changes, so only main.cpp rebuilds.
execute_process(COMMAND git describe --always --dirty --abbrev=12 WORKING_DIRECTORY "${SRC}"
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "#define SOFTRASTER_GIT_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
