#!/usr/bin/env bash
# Installs what the tests need, then builds and runs the whole suite twice: a Release build,
# and a build under AddressSanitizer + UndefinedBehaviorSanitizer.
#   scripts/test.sh            (both)
#   scripts/test.sh release    (Release only, faster while working)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
jobs=$(nproc)
source scripts/ccache.sh
run_suite() {  # name, cmake args...
  local dir="build-$1"; shift
  echo "=== $dir"
  cmake -S . -B "$dir" -G Ninja "${launcher[@]}" "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
  ctest --test-dir "$dir" -j "$jobs" --output-on-failure
}
# The course's lesson programs are built and their pictures checked in the Release build
# only (the sanitizer build of the lessons took twice as long); the unit tests check the
# lessons' code (tests/course) in both.
# (Installed to /usr, as the Debian packages are: the install tests check those.)
run_suite release -DCMAKE_BUILD_TYPE=Release -DSOFTRASTER_COURSE=ON -DCMAKE_INSTALL_PREFIX=/usr
if [ "${1:-}" != "release" ]; then
  # detect_leaks: LeakSanitizer is part of ASan; halt on the first UB report.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # -O0 -g1 (line tables: sanitizer reports keep file and line): the build is cheaper than
  # the suite's longer run (docs/performance.md, "Build time"). Pixels are the Release
  # build's to check: the llvmpipe comparisons run there only.
  run_suite asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g1 -DNDEBUG" -DSOFTRASTER_SANITIZE=ON -DSOFTRASTER_COURSE=OFF
fi
