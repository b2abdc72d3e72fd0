// The "lights" of scene files (docs/scene-format.md "Lights", "Shadows"), for scene_json.cpp.
#pragma once
#include "scene/json_node.h"
#include "softraster/scene/scene.h"

namespace softraster::scene_json {

// Reads `n` into `l`: ambient, directional, point and spot lights with their shadows (a file
// of `version` may use only that version's keys).
void read_lights(const Node& n, Lights& l, int version);

}  // namespace softraster::scene_json
