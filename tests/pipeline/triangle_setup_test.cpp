// Triangle setup (pipeline/triangle_setup.h): the pixel bounds hold every sample the triangle
// covers, with one sample per pixel and with 4x MSAA, and a triangle set up as touching
// nothing (binning drops these) covers no sample of the tile. Coverage here is an independent
// brute-force test of every sample against the three edges with the top-left rule.
// The interpolation planes, made four at a time, are each the plane formula's for its
// corner values, bit for bit, for every varying count.
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

namespace {

// setup_planes computes the varyings' and 1/w's planes four lanes at a time; each must be
// PlaneBasis::at_origin's plane of its corner values (varying times 1/w, or the varying
// itself for noperspective), rounded to float, bit for bit, whatever the varying count.
template <int N>
void expect_planes_of_the_corner_values(bool noperspective) {
    std::mt19937 rng(11 + N);
    std::uniform_real_distribution<float> u(0, 1);
    const Rect tile{64, 128, 128, 192};
    int checked = 0;
    for (int k = 0; k < 200; ++k) {
        std::array<ShadedVertex<N>, 3> p;
        for (ShadedVertex<N>& v : p) {
            v.window = {60 + 72 * u(rng), 124 + 72 * u(rng), u(rng), 0.05f + 2 * u(rng)};
            v.X = int32_t(snap_to_subpixel(v.window.x)), v.Y = int32_t(snap_to_subpixel(v.window.y));
            for (float& a : v.var) a = 10 * u(rng) - 5;
        }
        if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) == 0) continue;
        TriangleSetup<N> t;
        t.options.noperspective = noperspective;
        if (!setup_coverage<1>(p[0], p[1], p[2], FrontFace::CCW, tile, t)) continue;
        setup_planes(t);
        const PlaneBasis basis = plane_basis(t);
        auto expect_plane = [&](const Plane& got, double a0, double a1, double a2, const char* what, size_t i) {
            const auto [value, dadx, dady] = basis.at_origin(a0, a1, a2);
            EXPECT_EQ(got.a0, float(value)) << what << i << " of triangle " << k;
            EXPECT_EQ(got.dadx, float(dadx)) << what << i << " of triangle " << k;
            EXPECT_EQ(got.dady, float(dady)) << what << i << " of triangle " << k;
        };
        const ShadedVertex<N>&a = *t.corner[0], &b = *t.corner[1], &c = *t.corner[2];
        const double wa = noperspective ? 1.0 : a.window.inv_w, wb = noperspective ? 1.0 : b.window.inv_w,
                     wc = noperspective ? 1.0 : c.window.inv_w;
        for (size_t i = 0; i < size_t(N); ++i)
            expect_plane(t.var_w(i), a.var[i] * wa, b.var[i] * wb, c.var[i] * wc, "varying ", i);
        if (noperspective) {
            EXPECT_EQ(t.inv_w().a0, 1.0f);
            EXPECT_EQ(t.inv_w().dadx, 0.0f);
            EXPECT_EQ(t.inv_w().dady, 0.0f);
        } else {
            expect_plane(t.inv_w(), wa, wb, wc, "1/w", 0);
        }
        ++checked;
    }
    EXPECT_GT(checked, 150);
}

}  // namespace

TEST(SetupPlanes, AreThePlanesOfTheCornerValuesForEveryVaryingCount) {
    [&]<int... M>(std::integer_sequence<int, M...>) {
        (expect_planes_of_the_corner_values<M + 1>(false), ...);
        (expect_planes_of_the_corner_values<M + 1>(true), ...);
    }(std::make_integer_sequence<int, 10>());
}
