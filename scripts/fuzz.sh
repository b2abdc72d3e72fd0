#!/usr/bin/env bash
# Fuzzes one loader with libFuzzer (clang), under AddressSanitizer and UBSan.
#   scripts/fuzz.sh TARGET SECONDS      e.g. scripts/fuzz.sh model_gltf 600
#   scripts/fuzz.sh --list              the targets (tests/fuzz/fuzz_targets.h)
# Builds build-fuzz/ with clang, starts from tests/fuzz/corpus/TARGET plus, for model
# targets, the matching files of Debian's assimp-testmodels (for scene, mesh_obj and
# mesh_ply, the repository's own scenes and meshes), and runs for SECONDS. Inputs
# that crash, leak, trip a sanitizer or take over 20 s are copied to
# tests/fuzz/corpus/TARGET/ as crash-*, leak-*, timeout-*: fix the bug, keep the file (ctest's
# fuzz.replay runs every file there), commit both. Exit code 1 when something was found.
set -euo pipefail
cd "$(dirname "$0")/.."
targets="scene mesh_obj mesh_ply image_png image_jpg image_tga image_bmp model_gltf model_glb model_obj model_fbx model_stl model_ply model_dae model_3ds"
if [ "${1:-}" = "--list" ]; then echo "$targets" | tr ' ' '\n'; exit 0; fi
if [ $# -ne 2 ] || ! echo " $targets " | grep -q " $1 "; then
  echo "usage: scripts/fuzz.sh TARGET SECONDS (targets: scripts/fuzz.sh --list)" >&2
  exit 2
fi
target=$1 seconds=$2
command -v clang++ >/dev/null || { echo "scripts/fuzz.sh needs clang (apt-get install clang)" >&2; exit 2; }
scripts/install-deps.sh --tests
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DSOFTRASTER_SANITIZE=ON -DSOFTRASTER_FUZZ=ON >/dev/null
cmake --build build-fuzz --target "fuzz_$target" softraster_oiio >/dev/null
work=build-fuzz/corpus/$target
found=build-fuzz/found/$target
mkdir -p "$work" "$found" "tests/fuzz/corpus/$target"
cp -n tests/fuzz/corpus/"$target"/* "$work"/ 2>/dev/null || true
case $target in
  model_*) ext=${target#model_}
           find /usr/share/assimp/models -iname "*.$ext" -size -200k -exec cp -n {} "$work"/ \; 2>/dev/null || true ;;
  # Our own feature scenes whose pictures are at most 256x256 (bigger ones draw slowly under
  # the sanitizers), and our OBJ and PLY files for the mesh loaders.
  scene) python3 -c 'import json, shutil, sys
for f in sys.argv[2:]:
    i = json.load(open(f)).get("image", {})
    if i.get("width", 0) * i.get("height", 0) <= 256 * 256: shutil.copy(f, sys.argv[1])' "$work" tests/scenes/*.json ;;
  mesh_obj|mesh_ply) find tests bench -name "*.${target#mesh_}" -size -200k -exec cp -n {} "$work"/ \; ;;
esac
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan.supp
status=0
"build-fuzz/tests/fuzz_$target" "$work" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 \
  -artifact_prefix="$found/" -print_final_stats=1 || status=$?
shopt -s nullglob
new=("$found"/*)
if [ ${#new[@]} -gt 0 ]; then
  cp "${new[@]}" "tests/fuzz/corpus/$target/"
  echo "found ${#new[@]} input(s), copied to tests/fuzz/corpus/$target/: ${new[*]##*/}" >&2
  exit 1
fi
exit $status
