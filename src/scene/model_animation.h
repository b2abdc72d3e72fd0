// glTF (and other) node animations as assimp reads them, turned into our keyframes
// (animation.h), for model_assimp.cpp.
#pragma once
#include <map>
#include <memory>
#include <set>
#include <string>

#include <assimp/scene.h>

#include "softraster/scene/animation.h"

namespace softraster {

// The motion of each node the file's first animation moves, by node name. A channel whose
// keys cannot be used (times not increasing, values not finite, a zero quaternion) is left
// out and noted in `ignored`, as are the animations after the first and mesh and morph
// target animations: those nodes are drawn at rest.
std::map<std::string, std::shared_ptr<const NodeMotion>> read_node_motions(const aiScene& scene, std::set<std::string>& ignored);

}  // namespace softraster
