// A scene object's pipeline state (object_state.cpp).
#pragma once
#include "softraster/render_state.h"
#include "softraster/scene/scene.h"

namespace softraster {

// The pipeline state of an object (version 2 keys; defaults for version 1). Pixel
// rectangles (the scissor) scale with supersampling.
RenderState render_state(const SceneObject& o, int supersample);

}  // namespace softraster
