// Where a pixel is sampled: at its center, or with MSAA at the Direct3D standard sample
// positions for 2, 4, 8 and 16 samples (4 is the spec's rotated grid; OpenGL leaves the
// positions to the implementation, llvmpipe uses the same 4). Rasterization tests these points; binning and triangle setup
// use their extent to bound the pixels a triangle can cover (pixel_bounds).
#pragma once
#include <algorithm>
#include <array>

#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/simd.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

// Sample positions inside a pixel in 1/256 pixel, x right, y down from its top-left corner.
template <int Samples>
struct SamplePattern;
template <>
struct SamplePattern<1> {
    static constexpr std::array<int, 1> x = {128}, y = {128};
};
// Direct3D gives the positions in 1/16 pixel from the center (x right, y down): here
// 128 + 16 * offset.
template <>
struct SamplePattern<2> {  // (4, 4), (-4, -4)
    static constexpr std::array<int, 2> x = {192, 64}, y = {192, 64};
};
template <>
struct SamplePattern<4> {  // (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)
    static constexpr std::array<int, 4> x = {96, 224, 32, 160}, y = {32, 96, 160, 224};
};
template <>
struct SamplePattern<8> {  // (1,-3) (-1,3) (5,1) (-3,-5) (-5,5) (-7,-1) (3,7) (7,-7)
    static constexpr std::array<int, 8> x = {144, 112, 208, 80, 48, 16, 176, 240}, y = {80, 176, 144, 48, 208, 112, 240, 16};
};
template <>
struct SamplePattern<16> {  // (1,1) (-1,-3) (-3,2) (4,-1) (-5,-2) (2,5) (5,3) (3,-5) (-2,6) (0,-7) (-4,-6) (-6,4) (-8,0) (7,-4) (6,7) (-7,-8)
    static constexpr std::array<int, 16> x = {144, 112, 80, 192, 48, 160, 208, 176, 96, 128, 64, 32, 0, 240, 224, 16},
                                         y = {144, 80, 160, 112, 96, 208, 176, 48, 224, 16, 32, 192, 128, 64, 240, 0};
};

// The smallest box, in 1/256 pixel from a pixel's top-left corner, holding all its samples.
struct SampleExtent {
    int x_lo, x_hi, y_lo, y_hi;
};
template <int Samples>
constexpr SampleExtent sample_extent() {
    using P = SamplePattern<Samples>;
    return {*std::min_element(P::x.begin(), P::x.end()), *std::max_element(P::x.begin(), P::x.end()),
            *std::min_element(P::y.begin(), P::y.end()), *std::max_element(P::y.begin(), P::y.end())};
}

// Pixels with a sample inside the bounding box [m, M] of a snapped triangle (corners with
// 24.8 fixed-point X, Y): pixel i has its samples at 256 i + s with s in [lo, hi], so one
// may be inside only if 256 i + hi >= m and 256 i + lo <= M, i.e.
// ceil((m - hi) / 256) <= i <= floor((M - lo) / 256). Empty for most triangles of a mesh
// finer than the pixels: they fall between the samples and are dropped in binning.
// (Binning passes the extent as a value: one copy of it serves every sample count.)
// The four in one 4-lane vector: each corner as (X, Y, -X, -Y), whose minimum over the
// corners is (m_x, m_y, -M_x, -M_y), then the lanes' offsets and one shift. (Triangle setup
// runs this for every triangle in every tile; as twelve scalar minimums and maximums it was
// 2% of bench_many_spheres, docs/performance.md.) The negations and sums are done on
// unsigned lanes, where overflow is defined; nothing overflows in fact, since the clipper's
// guard band keeps the corners within 2^25 of 0.
template <class V>
inline Rect pixel_bounds(const V& a, const V& b, const V& c, const SampleExtent& s) {
    using simd::i4, simd::u4;
    // Lanes 0 and 1 kept, 2 and 3 negated: (x ^ 0) - 0 = x, (x ^ ~0) - ~0 = -x.
    auto negate_high = [](u4 v) { return (v ^ u4{0, 0, ~0u, ~0u}) - u4{0, 0, ~0u, ~0u}; };
    auto lanes = [&](const V& v) { return i4(negate_high(u4{uint32_t(v.X), uint32_t(v.Y), uint32_t(v.X), uint32_t(v.Y)})); };
    const i4 p = lanes(a), q = lanes(b), r = lanes(c);
    i4 m = p < q ? p : q;
    m = m < r ? m : r;
    constexpr uint32_t kRoundUp = uint32_t(kSubpixelOne - 1);  // ceil(v / 256) = floor((v + 255) / 256)
    const u4 offset = {kRoundUp - uint32_t(s.x_hi), kRoundUp - uint32_t(s.y_hi), 0u - uint32_t(s.x_lo), 0u - uint32_t(s.y_lo)};
    const i4 bounds = (i4(negate_high(u4(m)) + offset) >> kSubpixelBits) + i4{0, 0, 1, 1};
    return {bounds[0], bounds[1], bounds[2], bounds[3]};
}
template <int Samples, class V>
inline Rect pixel_bounds(const V& a, const V& b, const V& c) {
    return pixel_bounds(a, b, c, sample_extent<Samples>());
}

}  // namespace softraster
