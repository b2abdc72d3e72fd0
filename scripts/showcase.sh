#!/usr/bin/env bash
# Installs what softraster needs, builds it in Release mode and renders the built-in
# showcase scene to showcase.png (or the path given).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
source scripts/ccache.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSOFTRASTER_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build -j "$(nproc)" --target softraster
./build/softraster showcase -o "${1:-showcase.png}"
