// Stage 8, fragment shading: run the user's fragment shader for a pixel, then merge.
//
// The depth test runs before the shader (early-Z). That is invisible to the picture because
// shaders here cannot change depth, and a discarded fragment writes nothing either way; it
// saves the whole shading cost of hidden fragments. With MSAA the shader runs once per pixel,
// at the pixel center, and its color goes to every covered sample that passed.
#pragma once
#include "softraster/framebuffer.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/shader.h"

namespace softraster {

// Depth-tests samples `covered` of pixel (x, y) at depths z, and if any pass, shades the
// fragment with the varyings that make_varyings() returns and merges it.
template <int Samples, BlendMode B, Shader S, class MakeVaryings>
inline void shade_fragment(const S& shader, const RenderState& st, Framebuffer& fb, int x, int y,
                           unsigned covered, const float* z, float center_z, bool front_facing,
                           MakeVaryings&& make_varyings, uint64_t& shaded) {
    const size_t base = fb.sample_index(x, y);
    const unsigned pass = depth_test<Samples>(st, fb.depth_data() + base, covered, z);
    if (!pass) return;
    ++shaded;
    const typename S::Varyings v = make_varyings();
    const FragCoord frag{float(x) + 0.5f, float(y) + 0.5f, center_z, front_facing};
    glm::vec4 color;
    if (!shader.fragment(v, frag, color)) return;
    merge_fragment<Samples, B>(st, fb.color_data() + base, fb.depth_data() + base, pass, z, color);
}

// Rasterizes one set-up triangle (within its bounds) and shades what it covers; returns the
// number of fragments shaded.
template <int Samples, BlendMode B, Shader S>
uint64_t draw_triangle(const S& shader, const RenderState& st, Framebuffer& fb,
                       const TriangleSetup<kVaryingCount<typename S::Varyings>>& t) {
    using V = typename S::Varyings;
    uint64_t shaded = 0;
    rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
        const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // shaded at the pixel center
        shade_fragment<Samples, B>(shader, st, fb, px.x, px.y, px.mask, px.z.data(), interpolate_depth(t, i, j),
                                   t.front_facing, [&] { return from_array<V>(interpolate_perspective(t, i, j)); }, shaded);
    });
    return shaded;
}

}  // namespace softraster
