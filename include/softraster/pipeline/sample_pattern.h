// Where a pixel is sampled: at its center, or with 4x MSAA at the four positions of the
// spec's rotated-grid pattern. Rasterization tests these points; binning and triangle setup
// use their extent to bound the pixels a triangle can cover (pixel_bounds).
#pragma once
#include <algorithm>
#include <array>

#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

// Sample positions inside a pixel in 1/256 pixel, x right, y down from its top-left corner.
template <int Samples>
struct SamplePattern;
template <>
struct SamplePattern<1> {
    static constexpr std::array<int, 1> x = {128}, y = {128};
};
template <>
struct SamplePattern<4> {  // (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)
    static constexpr std::array<int, 4> x = {96, 224, 32, 160}, y = {32, 96, 160, 224};
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
template <int Samples, class V>
inline Rect pixel_bounds(const V& a, const V& b, const V& c) {
    constexpr SampleExtent s = sample_extent<Samples>();
    constexpr int kRoundUp = int(kSubpixelOne) - 1;
    return {(std::min({a.X, b.X, c.X}) - s.x_hi + kRoundUp) >> kSubpixelBits,
            (std::min({a.Y, b.Y, c.Y}) - s.y_hi + kRoundUp) >> kSubpixelBits,
            ((std::max({a.X, b.X, c.X}) - s.x_lo) >> kSubpixelBits) + 1,
            ((std::max({a.Y, b.Y, c.Y}) - s.y_lo) >> kSubpixelBits) + 1};
}

}  // namespace softraster
