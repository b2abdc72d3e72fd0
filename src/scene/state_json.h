// The per-fragment state keys of scene files (docs/scene-format.md: an object's "depth" and
// "stencil", a material's "blend" equation), for scene_json.cpp (state_json.cpp).
#pragma once
#include "scene/json_node.h"
#include "softraster/render_state.h"
#include "softraster/scene/scene.h"

namespace softraster::scene_json {

// A material's "blend" object: equations and factors for color and alpha, and the constant.
BlendEquationState read_blend_equation(const Node& n);
// An object's "depth" object into st.
void read_depth(const Node& n, ObjectState& st);
// An object's "stencil": one face state for both faces, or "front" and "back".
void read_stencil(const Node& n, ObjectState& st);

}  // namespace softraster::scene_json
