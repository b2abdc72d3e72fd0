// The version 2 "animation" keys of scene files (docs/scene-format.md "Animation"), for
// scene_json.cpp.
#pragma once
#include <memory>

#include "scene/json_node.h"
#include "softraster/scene/animation.h"

namespace softraster::scene_json {

// An object's keys; where no key gives translate, rotate or scale, the transform's value.
std::shared_ptr<const ObjectMotion> read_object_animation(const Node& n, const glm::vec3& translate, const glm::vec3& rotate,
                                                          const glm::vec3& scale);

// The camera's keys of eye and target (checked at every key against `camera`'s up).
std::shared_ptr<const CameraMotion> read_camera_animation(const Node& n, const Camera& camera);

}  // namespace softraster::scene_json
