#!/usr/bin/env bash
# Renders every conformance scene with softraster and with Mesa llvmpipe and writes the
# table of results into docs/conformance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build-release -j "$(nproc)"
python3 tests/reference/compare.py build-release/softraster build-release/tests/glref build-release/report \
  --report docs/conformance.md tests/conformance/*.json tests/scenes/*.json
