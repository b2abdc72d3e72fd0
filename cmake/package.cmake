# The Debian packages (`cpack -G DEB`, run by scripts/package.sh), split as Debian splits a
# library and its program:
#   softraster              the program (its library linked in: faster frames, see
#                           CMakeLists.txt), its window module (SDL2, for `view`), man
#                           pages, bash completion and the thumbnailer
#   libsoftraster0.1        the shared library
#   libsoftraster0.1-oiio   its OpenImageIO module, for SGI, DDS, TIFF, WebP, HDR and EXR
#                           textures: recommended, not required, because OpenImageIO brings
#                           hundreds of libraries (OpenCV, GDAL...) that a server or a
#                           container drawing glTF files does without
#   libsoftraster0.1-video  its FFmpeg module, for MP4 and WebM videos (`animate`):
#                           recommended, for the same reason (FFmpeg brings some 130
#                           libraries; GIFs and numbered pictures need no module)
#   libsoftraster-dev       headers, the .so link, the CMake package and softraster.pc
#   python3-softraster      the Python module (when pybind11 is installed)
# The library's package is named after its SONAME (libsoftraster.so.0.1, CMakeLists.txt).
# Each component sets its own Description (synopsis first).
# Dependencies on Debian's libraries come from dpkg-shlibdeps; the -dev and Python packages'
# on the library, and the -dev package's on libglm-dev, are declared here.
set(soname_version ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME softraster)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
# (The address the project's commits carry; a distributor sets their own.)
set(SOFTRASTER_MAINTAINER "softraster developers <maintainers@users.noreply.h-seed-5657c02a.example>" CACHE STRING "The packages' Maintainer")
set(CPACK_PACKAGE_CONTACT "${SOFTRASTER_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)  # (CPACK_COMPONENT_*_DEPENDS become Depends)
set(CPACK_COMPONENTS_ALL bin lib oiio video dev)
if(TARGET softraster_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# (Where dpkg-shlibdeps finds the program's own library, which no installed package provides yet.)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR})
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)

set(CPACK_DEBIAN_BIN_PACKAGE_NAME softraster)
set(CPACK_DEBIAN_BIN_PACKAGE_SECTION graphics)
set(CPACK_COMPONENT_BIN_DESCRIPTION "3D rasterizer that runs the whole graphics pipeline on the CPU
softraster renders scene files and model files (glTF, OBJ, FBX, STL,
COLLADA, 3DS, PLY and the other formats assimp reads) to pictures, videos
and thumbnails with no GPU and no display. Its pictures match Mesa's
llvmpipe. This package has the program, its man pages, bash completion,
and a thumbnailer that shows 3D models in file managers.")
# (The program links the library's static archive: it needs no other package of ours.)
set(CPACK_DEBIAN_BIN_PACKAGE_RECOMMENDS "libsoftraster${soname_version}-oiio (= ${PROJECT_VERSION}), libsoftraster${soname_version}-video (= ${PROJECT_VERSION})")

set(CPACK_DEBIAN_LIB_PACKAGE_NAME libsoftraster${soname_version})
set(CPACK_DEBIAN_LIB_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_LIB_DESCRIPTION "3D rasterizer on the CPU - shared library
softraster is a 3D rasterizer that runs the whole graphics pipeline on
the CPU, with pictures that match Mesa's llvmpipe. This package has the
shared library.")
set(CPACK_DEBIAN_LIB_PACKAGE_RECOMMENDS "libsoftraster${soname_version}-oiio (= ${PROJECT_VERSION}), libsoftraster${soname_version}-video (= ${PROJECT_VERSION})")
# ldconfig by trigger, as Debian wants it (CPack also writes postinst and postrm that run it).
set(CPACK_DEBIAN_LIB_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/packaging/triggers)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)  # (and the ldconfig trigger)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY "=")

set(CPACK_DEBIAN_OIIO_PACKAGE_NAME libsoftraster${soname_version}-oiio)
set(CPACK_DEBIAN_OIIO_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_OIIO_DESCRIPTION "3D rasterizer on the CPU - OpenImageIO textures
softraster is a 3D rasterizer that runs the whole graphics pipeline on
the CPU. This package has the module through which it reads SGI, DDS,
TIFF, WebP, HDR and EXR textures with OpenImageIO; PNG, JPEG, TGA and
BMP need no module.")

set(CPACK_DEBIAN_VIDEO_PACKAGE_NAME libsoftraster${soname_version}-video)
set(CPACK_DEBIAN_VIDEO_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_VIDEO_DESCRIPTION "3D rasterizer on the CPU - FFmpeg videos
softraster is a 3D rasterizer that runs the whole graphics pipeline on
the CPU. This package has the module through which it writes MP4 (H.264)
and WebM (VP9) videos with FFmpeg; GIFs and numbered pictures need no
module.")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-softraster)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_COMPONENT_PYTHON_DESCRIPTION "3D rasterizer on the CPU - Python module
softraster is a 3D rasterizer that runs the whole graphics pipeline on
the CPU. This package has its Python module: scene and model files drawn
into NumPy arrays (color, depth, normals, ids, cameras), with no GPU and
no display; softraster.dask draws folders of model files on a Dask cluster.")
set(CPACK_COMPONENT_PYTHON_DEPENDS lib)
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= 3.11), python3 (<< 3.12), python3-numpy")
# softraster.dask needs Dask and runs the program; the rest of the module needs neither.
set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-distributed, softraster")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME libsoftraster-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEV_DESCRIPTION "3D rasterizer on the CPU - development files
softraster is a 3D rasterizer that runs the whole graphics pipeline on
the CPU, with pictures that match Mesa's llvmpipe. This package has the
headers, the CMake package (find_package(softraster), target
softraster::softraster) and softraster.pc.")
set(CPACK_COMPONENT_DEV_DEPENDS lib)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libglm-dev")

# Each package's /usr/share/doc/<package>: the copyright file and the changelog Debian asks for.
foreach(component ${CPACK_COMPONENTS_ALL})
  string(TOUPPER ${component} upper)
  set(package ${CPACK_DEBIAN_${upper}_PACKAGE_NAME})
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component})
  install(FILES ${PROJECT_BINARY_DIR}/changelog.gz DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component})
endforeach()
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/changelog.gz
                   COMMAND sh -c "gzip -n -9 -c '${PROJECT_SOURCE_DIR}/packaging/changelog' > '${PROJECT_BINARY_DIR}/changelog.gz'"
                   DEPENDS ${PROJECT_SOURCE_DIR}/packaging/changelog VERBATIM)
add_custom_target(softraster_changelog ALL DEPENDS ${PROJECT_BINARY_DIR}/changelog.gz)

include(CPack)
