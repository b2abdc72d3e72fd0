// Lesson 8: from normalized device coordinates to pixels, into any rectangle of the picture
// (OpenGL's glViewport).
#pragma once
#include <glm/glm.hpp>

#include "../06-camera/camera.h"

namespace course {

// A viewport (视口): the rectangle of the picture that NDC's [-1, 1] square fills. x, y is its
// top-left pixel corner (y down, as the picture's rows).
struct ViewportRect {
    float x = 0, y = 0, width = 1, height = 1;
};

// The perspective divide, then the viewport transform (视口变换):
//   x_w = x + (ndc.x + 1) / 2 * width,  y_w = y + (1 - ndc.y) / 2 * height,  depth = (ndc.z + 1) / 2.
// y is flipped because NDC's y goes up and the rows go down.
inline ScreenPoint to_viewport(const glm::vec4& clip, const ViewportRect& v) {
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {v.x + (ndc.x + 1.0f) * 0.5f * v.width, v.y + (1.0f - ndc.y) * 0.5f * v.height, (ndc.z + 1.0f) * 0.5f};
}

// Back from a pixel position to NDC (for picking: which point of the scene is under the mouse).
inline glm::vec2 to_ndc(float x_w, float y_w, const ViewportRect& v) {
    return {2.0f * (x_w - v.x) / v.width - 1.0f, 1.0f - 2.0f * (y_w - v.y) / v.height};
}

}  // namespace course
