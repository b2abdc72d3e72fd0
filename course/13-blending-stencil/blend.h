// Lesson 13: the last per-pixel steps before a color is stored: the stencil test and
// blending. Colors are RGBA in [0, 1]; src is the fragment's, dst what the pixel holds.
#pragma once
#include <algorithm>
#include <cstdint>

#include <glm/glm.hpp>

#include "../10-shaders/shaders.h"

namespace course {

// Alpha blending (Alpha 混合, Porter & Duff's "over"): the fragment covers a fraction alpha of
// what is behind it. result = src * a + dst * (1 - a). Order matters: glass over a wall is
// not the wall over glass.
inline glm::vec3 blend_over(const glm::vec4& src, const glm::vec3& dst) { return glm::vec3(src) * src.a + dst * (1.0f - src.a); }

// Additive blending (加法混合): light adds up (fire, glows). result = src * a + dst; the same in
// any order.
inline glm::vec3 blend_additive(const glm::vec4& src, const glm::vec3& dst) { return glm::min(glm::vec3(src) * src.a + dst, glm::vec3(1.0f)); }

// The stencil test (模板测试): each pixel has an 8-bit stencil value beside its color and
// depth. A draw compares ref with it, (ref & mask) FUNC (stored & mask), and draws only where
// that holds; the stencil operations then change the stored value (here "replace": store ref
// where the draw passed). Drawing a shape into the stencil first, then drawing the scene
// only where the stencil holds that mark, cuts the scene to the shape (a portal, a mirror).
inline bool stencil_equal_passes(uint8_t ref, uint8_t stored, uint8_t mask = 0xff) { return (ref & mask) == (stored & mask); }

// A flat color with alpha, for the draws of this lesson.
struct FlatShader {
    using Vertex = MeshIn;
    using Varyings = SurfaceVaryings;
    glm::mat4 model, view_projection;
    glm::vec4 color;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out = {glm::mat3(model) * in.normal, in.position, in.color};
        return view_projection * model * glm::vec4(in.position, 1.0f);
    }
    bool fragment(const Varyings&, const softraster::FragCoord&, glm::vec4& c) const {
        c = color;
        return true;
    }
};

}  // namespace course
