# Sourced by the build scripts (showcase.sh, test.sh, package.sh): ccache, when installed,
# keeps compiled files between builds (a rebuild after a small change, or the same tree
# built again, takes seconds instead of minutes). Sets `launcher`, the CMake arguments.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# (The sloppiness lets it cache the files built with a precompiled header, see CMakeLists.txt.)
export CCACHE_SLOPPINESS=pch_defines,time_macros
