// Stage 10, attribute interpolation across a triangle, from the planes of triangle setup.
//
// Depth is affine in window space, so its plane gives it directly. Every other attribute a is
// affine in window space only after division by w, so setup made planes of a/w and 1/w, and
// a = (a/w)(x, y) / (1/w)(x, y)  (perspective-correct interpolation, Heckbert & Moreton 1991).
// (i, j) are pixel offsets from the planes' origin pixel; fractions address sample points.
#pragma once
#include <array>
#include <type_traits>

#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd.h"
#include "softraster/pipeline/triangle_setup.h"

namespace softraster {

// (i, j) as float for one point, or as simd::f8 for eight: the same arithmetic, lane by lane.
template <class T>
inline T interpolate_depth(const TriangleEdges& t, T i, T j) {
    return t.z.at(i, j);
}

// Flat: the shader's flat varyings (shader.h), whose planes hold the provoking vertex's
// value (setup_planes) and are not interpolated.
// Constant: the draw's planes were made looking for constant varyings (setup_planes); a
// triangle that has them has constant planes, each giving its value.
template <uint64_t Flat, bool Constant = false, int N, class T>
inline std::array<T, N> interpolate_perspective(const TriangleSetup<N>& t, T i, T j) {
    std::array<T, N> out;
    if constexpr (Constant) {
        if (t.constant_varyings) {
            for (size_t k = 0; k < size_t(N); ++k) out[k] = t.var_w(k).at(i, j);  // a0 + 0 i + 0 j: exactly a0
            return out;
        }
    }
    const T w = 1.0f / t.inv_w().at(i, j);
    for (size_t k = 0; k < size_t(N); ++k) {
        if ((Flat >> k) & 1) out[k] = t.var_w(k).at(i, j);  // a0 + 0 i + 0 j: exactly a0
        else out[k] = t.var_w(k).at(i, j) * w;
    }
    return out;
}

// 1 where the pixel's window coordinate origin + i is odd, else 0 (i: a whole offset).
inline float odd(int origin, float i) { return float((origin + int(i)) & 1); }
inline simd::f8 odd(int origin, simd::f8 i) { return simd::to_float((simd::splat_i(origin) + simd::to_int(i)) & 1); }

// The varyings shader S reads at pixel offset (i, j), perspective-correct; for a
// DerivativeShader (shader.h) with the derivatives of its varying a over the pixel's 2x2
// quad, the pixels of even and odd x by even and odd y (row 0 at the top). With (x0, y0) the
// quad's top-left pixel, as llvmpipe takes them:
//   da/dx = a(x0 + 1, y0) - a(x0, y0),   da/dy = a(x0, y0 + 1) - a(x0, y0),
// each a perspective-correct as above, whether or not those pixels are covered.
//
// Eight lanes that are eight pixels of a row, the first at an even x (a group of
// for_each_group), hold four whole quads' top or bottom rows: each quad's corners on this
// row are then lanes already computed, and only the other row needs a 1/w (two divisions
// a group instead of four). The values are the same, computed from the same numbers.
template <class S, bool Constant, int N>
inline bool quad_row_lanes(const TriangleSetup<N>& t, const simd::f8& i, const simd::f8& j) {
    if constexpr (Constant)
        if (t.constant_varyings) return false;
    return ((t.origin_x + int(i[0])) & 1) == 0 && !simd::any(i != simd::to_float(simd::kLaneIndex) + i[0]) && !simd::any(j != j[0]);
}
template <class S, int N>
inline std::array<simd::f8, N> interpolate_quad_rows(const TriangleSetup<N>& t, simd::f8 i, simd::f8 j) {
    using simd::f8;
    constexpr uint64_t Flat = kFlatVaryings<S>;
    constexpr size_t a = size_t(S::kDerivativeOf), at = size_t(S::kDerivativeAt);
    std::array<f8, N> out;
    static_assert(((Flat >> a) & 3) == 0, "the varying with derivatives is interpolated");
    const f8 w = 1.0f / t.inv_w().at(i, j);  // (interpolate_perspective)
    for (size_t k = 0; k < size_t(N); ++k) {
        if (k >= at && k < at + 4) continue;  // (the derivatives, below)
        if ((Flat >> k) & 1) out[k] = t.var_w(k).at(i, j);
        else out[k] = t.var_w(k).at(i, j) * w;
    }
    const bool top = ((t.origin_y + int(j[0])) & 1) == 0;  // this row is the quads' first (y0)
    const f8 j_other = top ? j + 1.0f : j - 1.0f;
    const f8 w_other = 1.0f / t.inv_w().at(i, j_other);
    auto even = [](const f8& v) { return __builtin_shufflevector(v, v, 0, 0, 2, 2, 4, 4, 6, 6); };
    auto odd = [](const f8& v) { return __builtin_shufflevector(v, v, 1, 1, 3, 3, 5, 5, 7, 7); };
    for (size_t c = 0; c < 2; ++c) {
        const f8 here = out[a + c], there = t.var_w(a + c).at(i, j_other) * w_other;
        const f8 row0 = top ? here : there, row1 = top ? there : here;  // a at rows y0 and y0 + 1
        const f8 v00 = even(row0);
        out[at + c] = odd(row0) - v00;
        out[at + 2 + c] = even(row1) - v00;
    }
    return out;
}

// Both rows of a row of quads, j0 the first's offset (quad_row_lanes holds for it): each
// row as interpolate_quad_rows gives it, from the same numbers, but each row's 1/w and the
// derivatives computed once for the two.
template <class S, int N>
inline void interpolate_quad_row_pair(const TriangleSetup<N>& t, const simd::f8& i, const simd::f8& j0, std::array<simd::f8, size_t(N)>& first,
                                      std::array<simd::f8, size_t(N)>& second) {
    using simd::f8;
    constexpr uint64_t Flat = kFlatVaryings<S>;
    constexpr size_t a = size_t(S::kDerivativeOf), at = size_t(S::kDerivativeAt);
    static_assert(((Flat >> a) & 3) == 0, "the varying with derivatives is interpolated");
    const f8 j1 = j0 + 1.0f;
    const f8 w0 = 1.0f / t.inv_w().at(i, j0), w1 = 1.0f / t.inv_w().at(i, j1);
    // Built in locals and stored at the end: stores through first and second (floats) could
    // alias the planes, which would then be loaded again after each.
    std::array<f8, size_t(N)> top, bottom;
    for (size_t k = 0; k < size_t(N); ++k) {
        if (k >= at && k < at + 4) continue;  // (the derivatives, below)
        if ((Flat >> k) & 1) top[k] = t.var_w(k).at(i, j0), bottom[k] = t.var_w(k).at(i, j1);
        else top[k] = t.var_w(k).at(i, j0) * w0, bottom[k] = t.var_w(k).at(i, j1) * w1;
    }
    for (size_t c = 0; c < 2; ++c) {
        const f8 row0 = top[a + c], row1 = bottom[a + c];  // (a is not flat: the same values as p.at * w)
        const f8 v00 = __builtin_shufflevector(row0, row0, 0, 0, 2, 2, 4, 4, 6, 6);
        top[at + c] = bottom[at + c] = __builtin_shufflevector(row0, row0, 1, 1, 3, 3, 5, 5, 7, 7) - v00;
        top[at + 2 + c] = bottom[at + 2 + c] = __builtin_shufflevector(row1, row1, 0, 0, 2, 2, 4, 4, 6, 6) - v00;
    }
    first = top, second = bottom;
}

template <class S, bool Constant = false, int N, class T>
inline std::array<T, N> interpolate_varyings(const TriangleSetup<N>& t, T i, T j) {
    if constexpr (DerivativeShader<S> && std::is_same_v<T, simd::f8>) {
        if (quad_row_lanes<S, Constant>(t, i, j)) return interpolate_quad_rows<S>(t, i, j);
    }
    std::array<T, N> out = interpolate_perspective<kFlatVaryings<S>, Constant>(t, i, j);
    if constexpr (DerivativeShader<S>) {
        constexpr size_t a = size_t(S::kDerivativeOf), at = size_t(S::kDerivativeAt);
        static_assert(((kFlatVaryings<S> >> at) & 15) == 15, "the derivatives' floats are flat varyings");
        if constexpr (Constant)
            if (t.constant_varyings) return out;  // (they stay 0)
        const T i0 = i - odd(t.origin_x, i), j0 = j - odd(t.origin_y, j), i1 = i0 + 1.0f, j1 = j0 + 1.0f;
        const T w00 = 1.0f / t.inv_w().at(i0, j0), w10 = 1.0f / t.inv_w().at(i1, j0), w01 = 1.0f / t.inv_w().at(i0, j1);
        for (size_t c = 0; c < 2; ++c) {
            const Plane p = t.var_w(a + c);
            const T v00 = p.at(i0, j0) * w00;
            out[at + c] = p.at(i1, j0) * w10 - v00;
            out[at + 2 + c] = p.at(i0, j1) * w01 - v00;
        }
    }
    return out;
}

}  // namespace softraster
