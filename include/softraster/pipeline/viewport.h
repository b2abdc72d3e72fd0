// Stage 4, perspective divide and viewport mapping: clip space -> window space.
//
//   ndc = clip.xyz / clip.w
//   x_w = (ndc.x + 1) / 2 * width
//   y_w = (1 - ndc.y) / 2 * height     (row 0 is the top row of the picture)
//   z_w = (ndc.z + 1) / 2              (depth range [0, 1])
// 1/w is kept: interpolating a/w and 1/w linearly in window space and dividing gives
// perspective-correct attributes (Heckbert & Moreton 1991; see interpolation.h).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "softraster/pipeline/clipping.h"

namespace softraster {

struct WindowPosition {
    float x = 0, y = 0, z = 0;  // window coordinates, pixels (y down) and depth
    float inv_w = 1;            // 1 / clip.w
};

// A window position with its varyings (lines and points; a triangle's vertices keep their
// varyings once, in ClipVertex, see vertex_processing.h).
template <int N>
struct WindowVertex : WindowPosition {
    std::array<float, N> var{};
};

struct Viewport {
    int width = 1, height = 1;
};

inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixelOne = int64_t(1) << kSubpixelBits;

// Window coordinate (pixels) -> 24.8 fixed point, round to nearest.
inline int64_t snap_to_subpixel(float v) { return int64_t(std::lrint(double(v) * double(kSubpixelOne))); }

// Window x, y, z and 1/w of clip position (x, y, z, w), for one vertex (float) or eight
// (simd::f8) with the same operations, so both give the same bits.
template <class T>
std::array<T, 4> window_coordinates(T x, T y, T z, T w, const Viewport& vp) {
    const T inv_w = 1.0f / w;
    return {(x * inv_w + 1.0f) * 0.5f * float(vp.width), (1.0f - y * inv_w) * 0.5f * float(vp.height), (z * inv_w + 1.0f) * 0.5f, inv_w};
}

// Returns false for a vertex that cannot be mapped (w <= 0 or a non-finite result); after
// clipping this only happens with degenerate user matrices, and the primitive is dropped.
inline bool to_window(const glm::vec4& clip, const Viewport& vp, WindowPosition& out) {
    if (!(clip.w > 0.0f)) return false;
    const auto [x, y, z, inv_w] = window_coordinates(clip.x, clip.y, clip.z, clip.w, vp);
    out = {x, y, z, inv_w};
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && std::isfinite(inv_w);
}

template <int N>
bool to_window(const ClipVertex<N>& c, const Viewport& vp, WindowVertex<N>& out) {
    out.var = c.var;
    return to_window(c.position, vp, static_cast<WindowPosition&>(out));
}

}  // namespace softraster
