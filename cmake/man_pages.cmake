# The man pages, written from the program's own help by help2man, so that they say what
# --help says: softraster.1, and softraster-COMMAND.1 for each command (each also gzipped,
# as Debian installs them). Run by the build (cmake/install.cmake):
#   cmake -DEXE=... -DOUT=... -DVERSION=... -DCOMMANDS="render;..." -DHELP2MAN=... -P man_pages.cmake
file(GLOB stale ${OUT}/*.1 ${OUT}/*.1.gz)  # (a command removed leaves no page behind)
if(stale)
  file(REMOVE ${stale})
endif()
file(MAKE_DIRECTORY ${OUT}/wrappers)
set(see_also "[SEE ALSO]\n.BR softraster (1)")
foreach(command ${COMMANDS})
  string(APPEND see_also ",\n.BR softraster-${command} (1)")
endforeach()
file(WRITE ${OUT}/see_also.h2m "${see_also}\n")

# help2man runs a program with --help: each command gets a two-line wrapper of its own.
function(write_page program name description)
  execute_process(COMMAND ${HELP2MAN} --no-info --no-discard-stderr --version-string=${VERSION} --name=${description}
                          --include=${OUT}/see_also.h2m --output=${OUT}/${name}.1 ${program}
                  RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "help2man failed for ${name}")
  endif()
  execute_process(COMMAND gzip -n -9 -c ${OUT}/${name}.1 OUTPUT_FILE ${OUT}/${name}.1.gz)
endfunction()

write_page(${EXE} softraster "render 3D scene files and model files to pictures on the CPU")
foreach(command ${COMMANDS})
  set(wrapper ${OUT}/wrappers/softraster-${command})
  file(WRITE ${wrapper} "#!/bin/sh\nexec '${EXE}' ${command} \"$@\"\n")
  file(CHMOD ${wrapper} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
  execute_process(COMMAND ${EXE} ${command} --help OUTPUT_VARIABLE help)
  string(REGEX MATCH "^[^\n]*" description "${help}")  # (CLI11 prints the command's description first)
  string(TOLOWER "${description}" first)
  string(SUBSTRING "${first}" 0 1 first)
  string(SUBSTRING "${description}" 1 -1 rest)
  write_page(${wrapper} softraster-${command} "${first}${rest}")
endforeach()
