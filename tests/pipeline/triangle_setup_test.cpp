// Triangle setup (pipeline/triangle_setup.h): the pixel bounds hold every sample the triangle
// covers, with one sample per pixel and with 4x MSAA, and a triangle set up as touching
// nothing (binning drops these) covers no sample of the tile. Coverage here is an independent
// brute-force test of every sample against the three edges with the top-left rule.
#include <gtest/gtest.h>

#include <random>

#include "softraster/pipeline/rasterization.h"
#include "test_support.h"

using namespace softraster;
using test::random_triangle;

namespace {

// Is the point (px, py), in 1/256 pixel, inside the snapped triangle? (Giesen 2013: orient
// clockwise on screen; an edge owns its points only if it is a top or a left edge.)
bool covers(std::array<ShadedVertex<1>, 3> p, int64_t px, int64_t py) {
    if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) < 0) std::swap(p[1], p[2]);
    for (size_t i = 0; i < 3; ++i) {
        const ShadedVertex<1>&a = p[i], &c = p[(i + 1) % 3];
        const int64_t dx = int64_t(c.X) - a.X, dy = int64_t(c.Y) - a.Y;
        const int64_t e = dx * (py - a.Y) - dy * (px - a.X);
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        if (e < 0 || (e == 0 && !top_left)) return false;
    }
    return true;
}

template <int Samples>
void expect_bounds_hold_every_covered_sample() {
    using P = SamplePattern<Samples>;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    const Rect tile{64, 128, 128, 192};
    int covering = 0, dropped = 0;
    for (int k = 0; k < 6000; ++k) {
        // mostly smaller than a pixel (the case the bounds exist for), some a few pixels big
        const float cx = 60 + 72 * u(rng), cy = 124 + 72 * u(rng);
        const float size = k % 4 == 0 ? 6 * u(rng) : 1.2f * u(rng);
        std::array<ShadedVertex<1>, 3> p;
        ASSERT_TRUE(random_triangle(rng, cx, cy, size, size * u(rng) * 2, p));
        if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) == 0) continue;
        TriangleSetup<1> t;
        const bool set_up = setup_coverage<Samples>(p[0], p[1], p[2], FrontFace::CCW, tile, t);
        bool any = false;
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                for (size_t s = 0; s < size_t(Samples); ++s) {
                    if (!covers(p, int64_t(x) * kSubpixelOne + P::x[s], int64_t(y) * kSubpixelOne + P::y[s])) continue;
                    any = true;
                    ASSERT_TRUE(set_up) << "triangle " << k << " covers (" << x << ", " << y << ") sample " << s;
                    ASSERT_TRUE(x >= t.bounds.x0 && x < t.bounds.x1 && y >= t.bounds.y0 && y < t.bounds.y1)
                        << "triangle " << k << " covers (" << x << ", " << y << ") outside its bounds";
                }
        covering += any;
        dropped += !set_up;
    }
    EXPECT_GT(covering, 400);
    EXPECT_GT(dropped, 1000);  // most sub-pixel triangles fall between the samples
}

TEST(PixelBounds, HoldEveryCoveredSample) { expect_bounds_hold_every_covered_sample<1>(); }
TEST(PixelBounds, HoldEveryCoveredSampleMsaa) { expect_bounds_hold_every_covered_sample<4>(); }

}  // namespace
