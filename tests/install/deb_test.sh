#!/usr/bin/env bash
# deb_test.sh BUILD WORK: the Debian packages from `cpack -G DEB` (as scripts/package.sh makes
# them): split in five, their dependencies from dpkg-shlibdeps and resolvable from Debian's
# archive, the files each holds, and no lintian errors.
set -euo pipefail
build=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
(cd "$build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1) || { tail -20 "$work/cpack.log"; fail "cpack"; }
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
bin=$work/softraster_${version}_amd64.deb lib=$work/libsoftraster0.1_${version}_amd64.deb dev=$work/libsoftraster-dev_${version}_amd64.deb
oiio=$work/libsoftraster0.1-oiio_${version}_amd64.deb video=$work/libsoftraster0.1-video_${version}_amd64.deb
for deb in "$bin" "$lib" "$oiio" "$video" "$dev"; do [ -f "$deb" ] || fail "no $(basename "$deb") (made: $(ls "$work"/*.deb 2>/dev/null | xargs -n1 basename))"; done

field() { dpkg-deb -f "$1" "$2"; }
# The program has the library linked in (and recommends the modules); every package's Debian
# dependencies are found.
if field "$bin" Depends | grep -q "libsoftraster0.1"; then fail "softraster depends on the library: $(field "$bin" Depends)"; fi
field "$bin" Recommends | grep -q "libsoftraster0.1-oiio (= $version)" || fail "softraster Recommends: $(field "$bin" Recommends)"
field "$bin" Recommends | grep -q "libsoftraster0.1-video (= $version)" || fail "softraster Recommends: $(field "$bin" Recommends)"
field "$bin" Depends | grep -q "libassimp5" || fail "softraster Depends lacks what dpkg-shlibdeps finds: $(field "$bin" Depends)"
field "$lib" Depends | grep -q "libassimp5" || fail "libsoftraster0.1 Depends: $(field "$lib" Depends)"
# OpenImageIO and FFmpeg (hundreds of libraries) only through the modules' packages, which the
# program and the library recommend.
for deb in "$bin" "$lib"; do
  if field "$deb" Depends | grep -q "openimageio"; then fail "$(basename "$deb") depends on OpenImageIO"; fi
  if field "$deb" Depends | grep -q "libavcodec"; then fail "$(basename "$deb") depends on FFmpeg: $(field "$deb" Depends)"; fi
done
field "$lib" Recommends | grep -q "libsoftraster0.1-oiio (= $version)" || fail "libsoftraster0.1 Recommends: $(field "$lib" Recommends)"
field "$lib" Recommends | grep -q "libsoftraster0.1-video (= $version)" || fail "libsoftraster0.1 Recommends: $(field "$lib" Recommends)"
field "$oiio" Depends | grep -q "libopenimageio" || fail "libsoftraster0.1-oiio Depends: $(field "$oiio" Depends)"
field "$video" Depends | grep -q "libavcodec" || fail "libsoftraster0.1-video Depends: $(field "$video" Depends)"
field "$dev" Depends | grep -q "libglm-dev" || fail "libsoftraster-dev Depends: $(field "$dev" Depends)"
field "$dev" Depends | grep -q "libsoftraster0.1 (= $version)" || fail "libsoftraster-dev Depends: $(field "$dev" Depends)"
# What each holds.
holds() { local files; files=$(dpkg-deb -c "$1" | awk '{print $6}'); grep -qx "$2" <<<"$files" || fail "$(basename "$1") lacks $2"; }
holds "$bin" ./usr/bin/softraster
holds "$bin" ./usr/lib/x86_64-linux-gnu/softraster/libsoftraster_window.so
holds "$bin" ./usr/share/man/man1/softraster.1.gz
holds "$bin" ./usr/share/man/man1/softraster-thumbnail.1.gz
holds "$bin" ./usr/share/bash-completion/completions/softraster
holds "$bin" ./usr/share/thumbnailers/softraster.thumbnailer
holds "$bin" ./usr/share/mime/packages/softraster-models.xml
holds "$lib" ./usr/lib/x86_64-linux-gnu/libsoftraster.so.$version
holds "$oiio" ./usr/lib/x86_64-linux-gnu/softraster/libsoftraster_oiio.so
holds "$video" ./usr/lib/x86_64-linux-gnu/softraster/libsoftraster_video.so
holds "$dev" ./usr/include/softraster/context.h
holds "$dev" ./usr/lib/x86_64-linux-gnu/cmake/softraster/softrasterConfig.cmake
holds "$dev" ./usr/lib/x86_64-linux-gnu/pkgconfig/softraster.pc
# The Python module, where pybind11 was found.
python=$work/python3-softraster_${version}_amd64.deb
if [ -f "$python" ]; then
  holds "$python" ./usr/lib/python3/dist-packages/softraster/__init__.py
  python_files=$(dpkg-deb -c "$python")
  grep -q "dist-packages/softraster/_softraster.cpython-" <<<"$python_files" || fail "python3-softraster lacks the compiled module"
  field "$python" Depends | grep -q "python3-numpy" || fail "python3-softraster Depends: $(field "$python" Depends)"
fi
lib_files=$(dpkg-deb -c "$lib")
if grep -q "/libsoftraster\.so$" <<<"$lib_files"; then fail "the library package holds the .so link (it is the -dev package's)"; fi
# It runs ldconfig when installed, and says which package provides its SONAME (shlibs).
dpkg-deb --ctrl-tarfile "$lib" | tar -xO ./triggers 2>/dev/null | grep -q "activate-noawait ldconfig" || fail "libsoftraster0.1 has no ldconfig trigger"
dpkg-deb --ctrl-tarfile "$lib" | tar -xO ./shlibs 2>/dev/null | grep -q "libsoftraster 0.1 libsoftraster0.1 (= $version)" || fail "libsoftraster0.1 has no shlibs"
# A clean Debian machine could install them: every dependency resolves against the archive.
apt-get install --simulate --no-install-recommends "$work"/*.deb >"$work/apt.log" 2>&1 || { tail -5 "$work/apt.log"; fail "apt-get cannot resolve the packages' dependencies"; }
lintian --fail-on error --tag-display-limit 0 "$work"/*.deb >"$work/lintian.log" 2>&1 || { grep "^E:" "$work/lintian.log"; fail "lintian reports errors"; }
echo "1 passed, 0 failed"
