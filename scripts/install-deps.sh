#!/usr/bin/env bash
# Installs everything softraster needs on Debian 12 from Debian's own packages.
# Usage: scripts/install-deps.sh [--tests]   (--tests adds what only the test suite needs)
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
pkgs=(cmake ninja-build g++ pkg-config python3
      libglm-dev libstb-dev nlohmann-json3-dev libcli11-dev libopenexr-dev libpng-dev libnetpbm-dev
      libopenimageio-dev libassimp-dev
      libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libgif-dev libimagequant-dev libchafa-dev libsleef-dev
      libsdl2-dev libsdl2-ttf-dev libx11-dev fonts-dejavu-core help2man
      pybind11-dev python3-dev python3-numpy)
if [ "${1:-}" = "--tests" ]; then
  # GoogleTest and Google Benchmark for the suite; OSMesa (Mesa llvmpipe) is the test-only reference;
  # assimp-testmodels: the corpus of real model files the thumbnails test renders.
  # ffmpeg: ffprobe and ffmpeg read the animations back; tmux shows the terminal preview;
  # Xvfb and xdotool run the viewer's window and type into it; xwd (x11-apps) reads it back.
  # ccache: test.sh builds two trees; it keeps their compiled files for the next run.
  # bubblewrap runs the thumbnailer in GNOME's sandbox; lintian checks the .deb packages.
  # python3-distributed: Dask, whose LocalCluster runs softraster.dask's test.
  pkgs+=(libgtest-dev libbenchmark-dev libosmesa6-dev assimp-testmodels ffmpeg tmux xvfb xauth xdotool x11-apps ccache
         bubblewrap lintian python3-distributed)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
