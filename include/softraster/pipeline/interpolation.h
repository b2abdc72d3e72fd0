// Attribute interpolation across a triangle.
//
// Screen-space barycentrics are l_i = E_i(p) / 2A (triangle_setup.h). Depth is affine in
// window space, so it uses them directly. Every other attribute a is affine in window space
// only after division by w, so we interpolate a/w and 1/w and divide (perspective-correct
// interpolation, Heckbert & Moreton 1991):
//   a(p) = (sum l_i a_i / w_i) / (sum l_i / w_i) = sum b_i a_i,  b_i = (l_i / w_i) / sum_j (l_j / w_j).
#pragma once
#include <array>

#include "softraster/pipeline/triangle_setup.h"

namespace softraster {

struct Barycentrics {
    float l0, l1, l2;
};

template <int N>
inline Barycentrics screen_barycentrics(const TriangleSetup<N>& t, int64_t e0, int64_t e1, int64_t e2) {
    return {float(e0) * t.inv_area2, float(e1) * t.inv_area2, float(e2) * t.inv_area2};
}

// Window depth: the plane z0 + l1 (z1 - z0) + l2 (z2 - z0), as a GPU's setup computes it.
template <int N>
inline float interpolate_depth(const TriangleSetup<N>& t, const Barycentrics& l) {
    return t.z[0] + l.l1 * (t.z[1] - t.z[0]) + l.l2 * (t.z[2] - t.z[0]);
}

template <int N>
inline std::array<float, N> interpolate_perspective(const TriangleSetup<N>& t, const Barycentrics& l) {
    const float p0 = l.l0 * t.inv_w[0], p1 = l.l1 * t.inv_w[1], p2 = l.l2 * t.inv_w[2];
    const float inv_sum = 1.0f / (p0 + p1 + p2);
    const float b0 = p0 * inv_sum, b1 = p1 * inv_sum, b2 = p2 * inv_sum;
    std::array<float, N> out;
    for (size_t k = 0; k < size_t(N); ++k) out[k] = b0 * t.var[0][k] + b1 * t.var[1][k] + b2 * t.var[2][k];
    return out;
}

}  // namespace softraster
