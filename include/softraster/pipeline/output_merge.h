// Stage 9, output merge: the per-sample depth test, blending and the color write.
//
// Color is stored as 8-bit RGBA. Blending follows the spec's formulas on the stored 8-bit
// destination, computed in float and quantized once (exact to rounding):
//   alpha:    rgb = s.rgb s.a + d.rgb (1 - s.a),  a = s.a + d.a (1 - s.a)
//   additive: rgb = s.rgb s.a + d.rgb,            a = d.a
// The source is clamped to [0, 1] first, as for any fixed-point color attachment.
#pragma once
#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "softraster/framebuffer.h"
#include "softraster/render_state.h"

namespace softraster {

inline bool depth_passes(DepthFunc f, float z, float stored) {
    switch (f) {
        case DepthFunc::Never: return false;
        case DepthFunc::Less: return z < stored;
        case DepthFunc::Equal: return z == stored;
        case DepthFunc::LessEqual: return z <= stored;
        case DepthFunc::Greater: return z > stored;
        case DepthFunc::NotEqual: return z != stored;
        case DepthFunc::GreaterEqual: return z >= stored;
        case DepthFunc::Always: return true;
    }
    return false;
}

template <BlendMode B>
inline Rgba8 blend(const glm::vec4& src_unclamped, Rgba8 dst) {
    const glm::vec4 src = glm::clamp(src_unclamped, 0.0f, 1.0f);
    if constexpr (B == BlendMode::Opaque) {
        return quantize_rgba8(src);
    } else {
        const glm::vec4 d = glm::vec4(dst.r, dst.g, dst.b, dst.a) * (1.0f / 255.0f);
        const float a = src.a;
        if constexpr (B == BlendMode::Alpha) {
            return quantize_rgba8(glm::vec4(glm::vec3(src) * a + glm::vec3(d) * (1.0f - a), a + d.a * (1.0f - a)));
        } else {
            Rgba8 out = quantize_rgba8(glm::vec4(glm::vec3(src) * a + glm::vec3(d), 0.0f));
            out.a = dst.a;
            return out;
        }
    }
}

// Depth test of the covered samples of one pixel; returns the samples that pass.
template <int Samples>
inline unsigned depth_test(const RenderState& st, const float* stored, unsigned covered, const float* z) {
    if (!st.depth_test) return covered;
    unsigned pass = 0;
    for (int s = 0; s < Samples; ++s)
        if ((covered & (1u << s)) && depth_passes(st.depth_func, z[s], stored[s])) pass |= 1u << s;
    return pass;
}

// Writes one shaded fragment to the samples in `mask` (which passed the depth test).
template <int Samples, BlendMode B>
inline void merge_fragment(const RenderState& st, Rgba8* color, float* depth, unsigned mask, const float* z,
                           const glm::vec4& src) {
    for (int s = 0; s < Samples; ++s) {
        if (!(mask & (1u << s))) continue;
        if (st.depth_test && st.depth_write) depth[s] = z[s];
        if (st.color_write) color[s] = blend<B>(src, color[s]);
    }
}

}  // namespace softraster
