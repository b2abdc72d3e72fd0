#!/usr/bin/env bash
# install_test.sh BUILD SOURCE WORK: `cmake --install` into a staging folder (DESTDIR), then
# what a user of the installed tree does: the program and its man page, and examples/
# built against the installed library twice, through find_package(softraster) and through
# pkg-config, each run and its picture compared with the in-tree build's.
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
stage=$work/stage
DESTDIR=$stage cmake --install "$build" >/dev/null
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
root=$stage$prefix
libdir=$(dirname "$(find "$root" -name 'libsoftraster.so.*.*.*' | head -1)")
fail() { echo "FAIL: $*"; exit 1; }

# The tree: versioned library with its SONAME link, modules, headers, CMake and pkg-config files.
soname=$(objdump -p "$libdir"/libsoftraster.so.*.*.* | awk '/SONAME/ {print $2}')
[ "$soname" = "libsoftraster.so.0.1" ] || fail "SONAME is '$soname'"
[ -L "$libdir/$soname" ] && [ -L "$libdir/libsoftraster.so" ] || fail "library links missing in $libdir"
for f in "$libdir/softraster/libsoftraster_oiio.so" "$libdir/softraster/libsoftraster_video.so" "$libdir/softraster/libsoftraster_window.so" "$root/include/softraster/context.h" "$root/bin/softraster" \
         "$libdir/cmake/softraster/softrasterConfig.cmake" "$libdir/cmake/softraster/softrasterConfigVersion.cmake" \
         "$libdir/pkgconfig/softraster.pc" "$root/share/man/man1/softraster.1.gz" "$root/share/man/man1/softraster-render.1.gz" \
         "$root/share/bash-completion/completions/softraster" "$root/share/thumbnailers/softraster.thumbnailer" \
         "$root/share/mime/packages/softraster-models.xml"; do
  [ -e "$f" ] || fail "not installed: ${f#$stage}"
done
# Nothing of the build tree may leak into what is installed (paths baked into files).
if grep -rl --binary-files=text "$build" "$stage" >/dev/null; then fail "the build folder is named in: $(grep -rl --binary-files=text "$build" "$stage" | head -3)"; fi

# Neither the program nor the library loads OpenImageIO, FFmpeg or SDL2 when it starts (each
# has its module, src/io/modules.h): together some 280 libraries, 37 ms of every start.
for f in "$root/bin/softraster" "$libdir"/libsoftraster.so.*.*.*; do
  heavy=$(objdump -p "$f" | awk '/NEEDED/ {print $2}' | grep -E '^lib(OpenImageIO|avcodec|avformat|avutil|swscale|SDL2|X11)' || true)
  [ -z "$heavy" ] || fail "${f#$stage} links $(tr '\n' ' ' <<<"$heavy")"
done
# The installed program writes a video through the module where it was installed.
"$root/bin/softraster" animate "$src/tests/scenes/models/textured.glb" --size 32x32 --fps 5 --duration 0.4 -o "$work/spin.mp4" 2>"$work/animate.log" \
  || fail "installed softraster animate to MP4: $(cat "$work/animate.log")"
[ -s "$work/spin.mp4" ] || fail "installed softraster animate wrote no video"

# The installed program runs and finds its library (and its module: an EXR texture needs it).
LD_LIBRARY_PATH=$libdir "$root/bin/softraster" showcase -o "$work/showcase.png" 2>/dev/null || fail "installed softraster showcase"
python3 - "$work/showcase.png" <<'PY' || fail "showcase picture"
import struct, sys
d = open(sys.argv[1], 'rb').read(24)
assert d[:8] == b'\x89PNG\r\n\x1a\n' and struct.unpack('>II', d[16:24])[0] > 0
PY

# The examples' pictures must be the in-tree build's, byte for byte.
"$build/example_triangle" "$work/reference.png" >/dev/null || fail "the in-tree example_triangle"
check_triangle() { cmp -s "$1" "$work/reference.png"; }

# examples/ through find_package.
cmake -S "$src/examples" -B "$work/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$root" >"$work/cmake.log" 2>&1 \
  || { cat "$work/cmake.log"; fail "examples: cmake with find_package(softraster)"; }
cmake --build "$work/examples" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; fail "examples: build"; }
"$work/examples/triangle" "$work/triangle_cmake.png" || fail "examples: run (find_package)"
check_triangle "$work/triangle_cmake.png" || fail "examples: picture (find_package)"

# The same through pkg-config (the staging folder as its sysroot), with the compiler's defaults.
flags=$(PKG_CONFIG_PATH=$libdir/pkgconfig PKG_CONFIG_SYSROOT_DIR=$stage pkg-config --cflags --libs softraster) || fail "pkg-config softraster"
# shellcheck disable=SC2086
${CXX:-c++} -O2 "$src/examples/triangle.cpp" -o "$work/triangle_pc" $flags || fail "examples: compile with pkg-config"
LD_LIBRARY_PATH=$libdir "$work/triangle_pc" "$work/triangle_pc.png" || fail "examples: run (pkg-config)"
check_triangle "$work/triangle_pc.png" || fail "examples: picture (pkg-config)"
echo "1 passed, 0 failed"
