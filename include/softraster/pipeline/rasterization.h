// Stage 7, rasterization: which samples of which pixels a set-up triangle covers.
//
// The edge functions are affine, so stepping one pixel right adds 256 A_i and one row down
// adds 256 B_i: the inner loop is integer additions and sign tests. Pixel (x, y) is sampled
// at its center (x + 0.5, y + 0.5), or with 4x MSAA at the four positions of the spec's
// pattern; each sample is covered when E_i + bias_i >= 0 for all three edges.
#pragma once
#include <array>
#include <cstdint>

#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/triangle_setup.h"

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

// One pixel the triangle touches: its covered samples and their depths.
template <int Samples>
struct CoveredPixel {
    int x = 0, y = 0;
    unsigned mask = 0;  // bit s set: sample s is covered
    std::array<float, Samples> z{};
};

// Calls on_pixel(const CoveredPixel<Samples>&) for every pixel of `rect` with coverage.
template <int Samples, int N, class OnPixel>
void rasterize_triangle(const TriangleSetup<N>& t, const Rect& rect, OnPixel&& on_pixel) {
    const int x0 = std::max(rect.x0, t.bounds.x0), x1 = std::min(rect.x1, t.bounds.x1);
    const int y0 = std::max(rect.y0, t.bounds.y0), y1 = std::min(rect.y1, t.bounds.y1);
    if (x0 >= x1 || y0 >= y1) return;

    using P = SamplePattern<Samples>;
    std::array<std::array<int64_t, Samples>, 3> sample_offset;  // E(sample) - E(center)
    std::array<int64_t, 3> row;                                 // E at the center of (x0, y)
    for (size_t i = 0; i < 3; ++i) {
        for (size_t s = 0; s < size_t(Samples); ++s)
            sample_offset[i][s] = t.A[i] * (P::x[s] - 128) + t.B[i] * (P::y[s] - 128);
        row[i] = t.edge(int(i), int64_t(x0) * kSubpixelOne + 128, int64_t(y0) * kSubpixelOne + 128);
    }

    CoveredPixel<Samples> px;
    for (int y = y0; y < y1; ++y) {
        std::array<int64_t, 3> e = row;
        for (int x = x0; x < x1; ++x) {
            unsigned mask = 0;
            for (size_t s = 0; s < size_t(Samples); ++s) {
                const int64_t s0 = e[0] + sample_offset[0][s] + t.bias[0];
                const int64_t s1 = e[1] + sample_offset[1][s] + t.bias[1];
                const int64_t s2 = e[2] + sample_offset[2][s] + t.bias[2];
                if ((s0 | s1 | s2) >= 0) mask |= 1u << s;
            }
            if (mask) {
                px.x = x;
                px.y = y;
                px.mask = mask;
                const float i = float(x - t.origin_x), j = float(y - t.origin_y);
                for (size_t s = 0; s < size_t(Samples); ++s)
                    if (mask & (1u << s))
                        px.z[s] = interpolate_depth(t, i + float(P::x[s] - 128) * (1.0f / 256.0f),
                                                    j + float(P::y[s] - 128) * (1.0f / 256.0f));
                on_pixel(px);
            }
            for (size_t i = 0; i < 3; ++i) e[i] += t.A[i] * kSubpixelOne;
        }
        for (size_t i = 0; i < 3; ++i) row[i] += t.B[i] * kSubpixelOne;
    }
}

}  // namespace softraster
