// Rasterization (pipeline/rasterization.h): row spans cover exactly the pixels whose centers
// the per-pixel edge test covers, for narrow rows (walked pixel by pixel) and wide rows
// (spans by division), triangles from a fraction of a pixel to far beyond the tile.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "softraster/pipeline/rasterization.h"
#include "test_support.h"

using namespace softraster;
using test::random_triangle;

namespace {

TEST(RowSpans, SameCoverageAsPerPixelTest) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0, 1);
    const Rect tile{64, 128, 128, 192};
    int small = 0, big = 0;
    for (int k = 0; k < 4000; ++k) {
        // sizes from a fraction of a pixel to far beyond the tile, thin ones included
        const float cx = 40 + 110 * u(rng), cy = 100 + 110 * u(rng);
        const float sx = 0.3f + 200 * u(rng) * u(rng) * u(rng), sy = 0.3f + 200 * u(rng) * u(rng) * u(rng);
        std::array<ShadedVertex<1>, 3> p;
        ASSERT_TRUE(random_triangle(rng, cx, cy, sx, sy, p));
        if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) == 0) continue;
        TriangleSetup<1> t;
        if (!setup_triangle<1>(p[0], p[1], p[2], FrontFace::CCW, tile, t)) continue;
        std::vector<int> expected(64 * 64, 0), got(64 * 64, 0);
        rasterize_triangle<1>(t, t.bounds, [&](const CoveredPixel<1>& px) { expected[size_t((px.y - tile.y0) * 64 + px.x - tile.x0)] = 1; });
        rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
            ASSERT_LT(x_begin, x_end);
            for (int x = x_begin; x < x_end; ++x) ++got[size_t((y - tile.y0) * 64 + x - tile.x0)];
        });
        ASSERT_EQ(expected, got) << "triangle " << k;
        ++(t.bounds.x1 - t.bounds.x0 <= kNarrow ? small : big);
    }
    EXPECT_GT(small, 500);
    EXPECT_GT(big, 300);
}

}  // namespace
