#!/usr/bin/env bash
# Installs what softraster needs, builds it in Release mode and renders the built-in
# showcase scene to showcase.png (or the path given).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# ccache, when installed, keeps compiled files for the next build of the same tree.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# (The sloppiness lets it cache the files built with a precompiled header, see CMakeLists.txt.)
export CCACHE_SLOPPINESS=pch_defines,time_macros
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSOFTRASTER_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build -j "$(nproc)" --target softraster
./build/softraster showcase -o "${1:-showcase.png}"
