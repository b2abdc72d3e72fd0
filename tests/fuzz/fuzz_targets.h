// The fuzz targets: each feeds one input, as a file of one format, to a loader. A loader may
// reject the input (InputError); anything else (a crash, a sanitizer report, an exception
// of another kind, a hang) is a bug. Built into libFuzzer programs by scripts/fuzz.sh, and
// into fuzz_replay, which ctest runs over every input kept in tests/fuzz/corpus.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace softraster::fuzz {

// The target names: scene, mesh_obj, mesh_ply, image_png, image_jpg, image_tga, image_bmp,
// model_gltf, model_glb, model_obj, model_fbx, model_stl, model_ply, model_dae, model_3ds.
std::vector<std::string> target_names();
// Runs one input through the target. Throws std::invalid_argument for an unknown target.
void run_target(const std::string& target, const uint8_t* data, size_t size);

}  // namespace softraster::fuzz
