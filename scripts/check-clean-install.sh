#!/usr/bin/env bash
# Installs the packages of scripts/package.sh on a clean Debian 12 (a minimal debootstrap
# chroot, nothing else installed) and checks what a user gets: the program, its man page,
# bash completion, pkg-config, find_package(softraster), the thumbnailer and a video (the
# FFmpeg module, recommended, which apt installs with the program). Needs root and
# Debian's archive; takes a few minutes (it downloads a base system and the dependencies).
#   scripts/package.sh && sudo scripts/check-clean-install.sh [dist] [chroot folder]
set -euo pipefail
cd "$(dirname "$0")/.."
dist=$(realpath "${1:-dist}") root=${2:-/tmp/softraster-clean-debian}
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >/dev/null
rm -rf "$root"
echo "debootstrap (minbase) into $root"
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >/dev/null
cp /etc/resolv.conf "$root/etc/resolv.conf"
mkdir -p "$root/tmp/dist" && cp "$dist"/*.deb "$root/tmp/dist/"
cp examples/triangle.cpp examples/CMakeLists.txt "$root/tmp/"
models=/usr/share/assimp/models  # (Debian's assimp-testmodels, on this machine)
cp "$models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb" "$models/PLY/Wuson.ply" "$root/tmp/"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root "$@"; }
in_root apt-get update -qq
echo "apt install the packages"
debs=$(cd "$root/tmp/dist" && printf '/tmp/dist/%s ' *.deb)
# shellcheck disable=SC2086
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $debs >/dev/null
in_root softraster --version
in_root softraster showcase -o /tmp/x.png
in_root dpkg-query -W -f='${Installed-Size} kB with dependencies: ' softraster; in_root du -sh /usr | cut -f1
echo "man, completion, thumbnailer (with the tools that read them)"
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq man-db bash-completion g++ cmake pkg-config >/dev/null
in_root man -P cat softraster-thumbnail | head -5
in_root bash -c 'source /usr/share/bash-completion/bash_completion; _completion_loader softraster; COMP_WORDS=(softraster thu); COMP_CWORD=1; _softraster; echo "completes: ${COMPREPLY[*]}"'
# The thumbnailer's line, with no HOME and no DISPLAY; a lying extension too.
grep '^Exec=' "$root/usr/share/thumbnailers/softraster.thumbnailer"
chroot "$root" /usr/bin/env -i PATH=/usr/bin softraster thumbnail --size 256 /tmp/BoxTextured.glb /tmp/box.png
cp "$root/tmp/Wuson.ply" "$root/tmp/wuson.stl"
chroot "$root" /usr/bin/env -i PATH=/usr/bin softraster thumbnail --size 256 /tmp/wuson.stl /tmp/wuson.png
ls -l "$root/tmp/box.png" "$root/tmp/wuson.png"
in_root softraster animate /tmp/BoxTextured.glb --size 64 --fps 5 --duration 0.4 -o /tmp/box.mp4
ls -l "$root/tmp/box.mp4"
in_root pkg-config --cflags --libs softraster
echo "find_package(softraster) and pkg-config builds of examples/triangle.cpp"
in_root cmake -S /tmp -B /tmp/build -DCMAKE_BUILD_TYPE=Release >/dev/null
in_root cmake --build /tmp/build >/dev/null
in_root /tmp/build/triangle /tmp/triangle.png
in_root sh -c 'c++ -O2 /tmp/triangle.cpp -o /tmp/triangle_pc $(pkg-config --cflags --libs softraster) && /tmp/triangle_pc /tmp/triangle_pc.png'
cmp "$root/tmp/triangle.png" "$root/tmp/triangle_pc.png" && echo "both builds draw the same picture"
echo "clean install: everything works"
