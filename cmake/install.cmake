# What `cmake --install` puts where, and the package files other projects find softraster by.
#
#   bin/softraster                               the program
#   lib/<arch>/libsoftraster.so.0.1               the library (and the .so link, for -dev)
#   lib/<arch>/softraster/libsoftraster_oiio.so   the OpenImageIO module it opens on demand
#   lib/<arch>/softraster/libsoftraster_video.so  the FFmpeg module, likewise (src/io/modules.h)
#   lib/<arch>/softraster/libsoftraster_window.so the program's SDL2 window, likewise
#   include/softraster/                          the public headers
#   lib/<arch>/cmake/softraster/                 softrasterConfig.cmake: softraster::softraster
#   lib/<arch>/pkgconfig/softraster.pc           pkg-config --cflags --libs softraster
#
# Components, one per Debian package (cmake/package.cmake): bin, lib, oiio and video (the
# modules) and dev.
include(CMakePackageConfigHelpers)

install(TARGETS softraster RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT bin)
install(TARGETS softraster_window LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/softraster COMPONENT bin)
install(TARGETS softraster_shared EXPORT softrasterTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT lib NAMELINK_COMPONENT dev
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS softraster_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/softraster COMPONENT oiio)
install(TARGETS softraster_video LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/softraster COMPONENT video)
install(DIRECTORY include/softraster DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/softraster)
install(EXPORT softrasterTargets NAMESPACE softraster:: DESTINATION ${config_dir} COMPONENT dev)
configure_package_config_file(cmake/softrasterConfig.cmake.in ${PROJECT_BINARY_DIR}/softrasterConfig.cmake INSTALL_DESTINATION ${config_dir})
# Before 1.0 a minor version may change the API: only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/softrasterConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/softrasterConfig.cmake ${PROJECT_BINARY_DIR}/softrasterConfigVersion.cmake
        DESTINATION ${config_dir} COMPONENT dev)

configure_file(cmake/softraster.pc.in ${PROJECT_BINARY_DIR}/softraster.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/softraster.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

# The commands, each with a man page. The test cli.man_pages checks this list against the
# command line's and every page against its command's --help.
set(SOFTRASTER_COMMANDS render showcase bench thumbnails thumbnail views animate view completion)
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(man_pages ${PROJECT_BINARY_DIR}/man/softraster.1)
  foreach(command ${SOFTRASTER_COMMANDS})
    list(APPEND man_pages ${PROJECT_BINARY_DIR}/man/softraster-${command}.1)
  endforeach()
  list(TRANSFORM man_pages APPEND .gz OUTPUT_VARIABLE man_pages_gz)
  add_custom_command(OUTPUT ${man_pages} ${man_pages_gz}
                     COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:softraster> -DOUT=${PROJECT_BINARY_DIR}/man -DVERSION=${PROJECT_VERSION}
                             "-DCOMMANDS=${SOFTRASTER_COMMANDS}" -DHELP2MAN=${HELP2MAN} -P ${PROJECT_SOURCE_DIR}/cmake/man_pages.cmake
                     DEPENDS softraster ${PROJECT_SOURCE_DIR}/cmake/man_pages.cmake
                     COMMENT "Writing the man pages (help2man)" VERBATIM)
  add_custom_target(softraster_man_pages ALL DEPENDS ${man_pages})
  install(FILES ${man_pages_gz} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT bin)
else()
  message(STATUS "help2man not found: no man pages (scripts/install-deps.sh installs it)")
endif()

# Bash completion, from the command tree (`softraster completion bash`).
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/completion/softraster
                   COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/completion
                   COMMAND sh -c "'$<TARGET_FILE:softraster>' completion bash > '${PROJECT_BINARY_DIR}/completion/softraster'"
                   DEPENDS softraster COMMENT "Writing the bash completion" VERBATIM)
add_custom_target(softraster_completion ALL DEPENDS ${PROJECT_BINARY_DIR}/completion/softraster)
install(FILES ${PROJECT_BINARY_DIR}/completion/softraster DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions COMPONENT bin)

# The freedesktop thumbnailer: file managers run `softraster thumbnail` for the model types
# listed there; the MIME types shared-mime-info lacks are declared by our own XML.
install(FILES data/softraster.thumbnailer DESTINATION ${CMAKE_INSTALL_DATADIR}/thumbnailers COMPONENT bin)
install(FILES data/softraster-models.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages COMPONENT bin)
