// Attribute interpolation across a triangle, from the planes of triangle setup.
//
// Depth is affine in window space, so its plane gives it directly. Every other attribute a is
// affine in window space only after division by w, so setup made planes of a/w and 1/w, and
// a = (a/w)(x, y) / (1/w)(x, y)  (perspective-correct interpolation, Heckbert & Moreton 1991).
#pragma once
#include <array>

#include "softraster/pipeline/triangle_setup.h"

namespace softraster {

// (x, y) is a window position, e.g. a pixel center (i + 0.5, j + 0.5).
template <int N>
inline float interpolate_depth(const TriangleSetup<N>& t, double x, double y) {
    return float(t.z.at(x - t.ref_x, y - t.ref_y));
}

template <int N>
inline std::array<float, N> interpolate_perspective(const TriangleSetup<N>& t, double x, double y) {
    const double dx = x - t.ref_x, dy = y - t.ref_y;
    const double w = 1.0 / t.inv_w.at(dx, dy);
    std::array<float, N> out;
    for (size_t k = 0; k < size_t(N); ++k) out[k] = float(t.var_w[k].at(dx, dy) * w);
    return out;
}

}  // namespace softraster
