# The Python module `softraster` (python/softraster, and its compiled part _softraster from
# src/python/module.cpp), for Debian's /usr/bin/python3 with pybind11 and NumPy from Debian
# (pybind11-dev, python3-numpy). Built when pybind11 is found; the build tree's
# python/ folder is importable (PYTHONPATH=build/python), which the tests use.
if(SOFTRASTER_SANITIZE)  # (an instrumented module cannot load into an uninstrumented python3)
  return()
endif()
# Debian's python3 (whose NumPy is python3-numpy), not another one first on the PATH.
if(EXISTS /usr/bin/python3 AND NOT Python3_EXECUTABLE)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module)
find_package(pybind11 CONFIG QUIET)
if(NOT pybind11_FOUND OR NOT Python3_FOUND)
  message(STATUS "pybind11 not found: no Python module (scripts/install-deps.sh installs pybind11-dev)")
  return()
endif()
set(python_dir ${PROJECT_BINARY_DIR}/python/softraster)
# (NO_EXTRAS: no link-time optimization, which recompiled the module serially at link time.)
pybind11_add_module(softraster_python MODULE NO_EXTRAS src/python/module.cpp src/cli/model_options.cpp)
set_target_properties(softraster_python PROPERTIES OUTPUT_NAME _softraster LIBRARY_OUTPUT_DIRECTORY ${python_dir})
target_include_directories(softraster_python PRIVATE src)
target_link_libraries(softraster_python PRIVATE softraster_shared)
target_compile_definitions(softraster_python PRIVATE SOFTRASTER_VERSION="${PROJECT_VERSION}")
# (pybind11 builds modules with hidden visibility; our headers' inline statics must still
# be the library's: the module only calls the library's functions, it instantiates no pipeline.)
file(GLOB python_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/softraster/*.py ${PROJECT_SOURCE_DIR}/python/softraster/*.pyi)
foreach(source ${python_sources})
  get_filename_component(name ${source} NAME)
  configure_file(${source} ${python_dir}/${name} COPYONLY)
endforeach()
# Installed where Debian's python3 finds packages; the module finds the library by its
# RPATH when the prefix is not /usr.
set(SOFTRASTER_PYTHON_DIR lib/python3/dist-packages CACHE STRING "Where the Python package is installed, under the prefix")
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  file(RELATIVE_PATH lib_from_python "${CMAKE_INSTALL_PREFIX}/${SOFTRASTER_PYTHON_DIR}/softraster" "${CMAKE_INSTALL_FULL_LIBDIR}")
  set_target_properties(softraster_python PROPERTIES INSTALL_RPATH "$ORIGIN/${lib_from_python}")
endif()
install(TARGETS softraster_python LIBRARY DESTINATION ${SOFTRASTER_PYTHON_DIR}/softraster COMPONENT python)
install(FILES ${python_sources} DESTINATION ${SOFTRASTER_PYTHON_DIR}/softraster COMPONENT python)
