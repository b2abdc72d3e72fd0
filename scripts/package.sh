#!/usr/bin/env bash
# Builds softraster's Debian packages into dist/ (cmake/package.cmake): softraster (the
# program), libsoftraster0.1 (the library), its modules libsoftraster0.1-oiio and
# libsoftraster0.1-video, libsoftraster-dev (headers, CMake and pkg-config files) and, where
# pybind11 is installed, python3-softraster.
#   scripts/package.sh && sudo apt install ./dist/*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
source scripts/ccache.sh
# The packages install to /usr; the tests and the course are not part of them.
cmake -S . -B build-package -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DSOFTRASTER_TESTS=OFF \
      -DSOFTRASTER_COURSE=OFF "${launcher[@]}" >/dev/null
cmake --build build-package -j "$(nproc)"
rm -rf dist
(cd build-package && cpack -G DEB -B "$PWD/../dist" >/dev/null)
rm -rf dist/_CPack_Packages
ls -1 dist/*.deb
echo "Install them with: sudo apt install ./dist/*.deb"
