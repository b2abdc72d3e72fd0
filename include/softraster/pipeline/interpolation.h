// Attribute interpolation across a triangle, from the planes of triangle setup.
//
// Depth is affine in window space, so its plane gives it directly. Every other attribute a is
// affine in window space only after division by w, so setup made planes of a/w and 1/w, and
// a = (a/w)(x, y) / (1/w)(x, y)  (perspective-correct interpolation, Heckbert & Moreton 1991).
// (i, j) are pixel offsets from the planes' origin pixel; fractions address sample points.
#pragma once
#include <array>

#include "softraster/pipeline/triangle_setup.h"

namespace softraster {

// (i, j) as float for one point, or as simd::f8 for eight: the same arithmetic, lane by lane.
template <int N, class T>
inline T interpolate_depth(const TriangleSetup<N>& t, T i, T j) {
    return t.z.at(i, j);
}

// Flat: the shader's flat varyings (shader.h), whose planes hold the provoking vertex's
// value (setup_planes) and are not interpolated.
// A triangle with constant varyings (setup_planes) has constant planes: each gives its value.
template <uint64_t Flat, int N, class T>
inline std::array<T, N> interpolate_perspective(const TriangleSetup<N>& t, T i, T j) {
    std::array<T, N> out;
    if (t.constant_varyings) {
        for (size_t k = 0; k < size_t(N); ++k) out[k] = t.var_w[k].at(i, j);  // a0 + 0 i + 0 j: exactly a0
        return out;
    }
    const T w = 1.0f / t.inv_w.at(i, j);
    for (size_t k = 0; k < size_t(N); ++k) {
        if ((Flat >> k) & 1) out[k] = t.var_w[k].at(i, j);  // a0 + 0 i + 0 j: exactly a0
        else out[k] = t.var_w[k].at(i, j) * w;
    }
    return out;
}

}  // namespace softraster
