// Where a pixel is sampled: at its center, or with 4x MSAA at the four positions of the
// spec's rotated-grid pattern. Rasterization tests these points; triangle setup and binning
// use their extent to bound the pixels a triangle can cover.
#pragma once
#include <algorithm>
#include <array>

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

}  // namespace softraster
