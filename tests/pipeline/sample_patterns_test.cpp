// 2x, 4x, 8x and 16x MSAA proved by properties (llvmpipe offers only 4x to compare with):
// through the whole pipeline, each sample is covered exactly when an independent
// point-in-triangle test with the top-left rule says so at its Direct3D position; shared
// edges cover each sample once; and a flat-colored scene resolves to the exact coverage
// fraction.
#include <algorithm>
#include <array>
#include <random>

#include <gtest/gtest.h>

#include "softraster/pipeline/sample_pattern.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 24, H = 20;

// Sample s of a pixel in pixels from its top-left corner, from the Direct3D table (1/16
// pixel from the center), written out here apart from sample_pattern.h.
glm::dvec2 d3d_position(int samples, int s) {
    static const int p2[][2] = {{4, 4}, {-4, -4}};
    static const int p4[][2] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
    static const int p8[][2] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
    static const int p16[][2] = {{1, 1},   {-1, -3}, {-3, 2},  {4, -1},  {-5, -2}, {2, 5},  {5, 3},   {3, -5},
                                 {-2, 6},  {0, -7},  {-4, -6}, {-6, 4},  {-8, 0},  {7, -4}, {6, 7},   {-7, -8}};
    const int(*p)[2] = samples == 2 ? p2 : samples == 4 ? p4 : samples == 8 ? p8 : p16;
    return {0.5 + p[s][0] / 16.0, 0.5 + p[s][1] / 16.0};
}

// Whether point q is inside triangle a, b, c (y down), samples on an edge counting only on
// a top edge (horizontal, the triangle below it) or a left edge (the triangle to its right).
bool inside(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 q) {
    const glm::dvec2 v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 p0 = v[i], p1 = v[(i + 1) % 3], other = v[(i + 2) % 3];
        auto side = [&](glm::dvec2 x) { return (p1.x - p0.x) * (x.y - p0.y) - (p1.y - p0.y) * (x.x - p0.x); };
        const double sq = side(q), so = side(other);
        if (sq == 0.0) {
            const bool top = p0.y == p1.y && other.y > p0.y;
            const bool left = p0.y != p1.y && other.x > p0.x + (p1.x - p0.x) * (other.y - p0.y) / (p1.y - p0.y);
            if (!top && !left) return false;
        } else if ((sq > 0) != (so > 0)) {
            return false;
        }
    }
    return true;
}

// Window positions on the 1/256 grid, so snapping leaves them where they are.
glm::dvec2 random_point(std::mt19937& rng) {
    std::uniform_int_distribution<int> x(-256 * 4, 256 * (W + 4)), y(-256 * 4, 256 * (H + 4));
    return {x(rng) / 256.0, y(rng) / 256.0};
}

ClipVertexIn vertex(glm::dvec2 p) { return {window_to_clip(float(p.x), float(p.y), W, H), 0}; }

// A white triangle on black, drawn with n samples per pixel; with `stencil`, under a stencil
// test every fragment passes, which sends the draw to the general back end's command.
Framebuffer white_triangle(int n, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, bool stencil = false) {
    Framebuffer fb(W, H, n);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    ctx.state.stencil_test = stencil;  // (the default faces: always pass, keep)
    draw(ctx, ConstantColorShader{glm::vec4(1)}, {vertex(a), vertex(b), vertex(c)}, {0, 1, 2});
    return fb;
}

class SamplePatterns : public ::testing::TestWithParam<int> {};

}  // namespace

TEST_P(SamplePatterns, EachSampleCoveredExactlyWhenInside) {
    const int n = GetParam();
    std::mt19937 rng(1234 + unsigned(n));
    int covered_total = 0;
    for (int trial = 0; trial < 150; ++trial) {
        const glm::dvec2 a = random_point(rng), b = random_point(rng), c = random_point(rng);
        const Framebuffer fb = white_triangle(n, a, b, c);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                for (int s = 0; s < n; ++s) {
                    const bool want = inside(a, b, c, glm::dvec2(x, y) + d3d_position(n, s));
                    const bool got = fb.color_data()[fb.sample_index(x, y, s)].r == 255;
                    covered_total += got;
                    ASSERT_EQ(got, want) << "samples " << n << " trial " << trial << " pixel " << x << "," << y << " sample " << s;
                }
    }
    EXPECT_GT(covered_total, 1000);
}

TEST_P(SamplePatterns, SharedEdgesCoverEachSampleOnce) {
    // A fan of triangles around a center, added up (additive blending): no sample may get two.
    const int n = GetParam();
    std::mt19937 rng(99 + unsigned(n));
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<ClipVertexIn> v = {vertex(random_point(rng))};
        for (int k = 0; k < 9; ++k) v.push_back(vertex(random_point(rng)));
        std::vector<uint32_t> idx;
        for (uint32_t k = 1; k < 10; ++k) idx.insert(idx.end(), {0, k, k % 9 + 1});
        Framebuffer fb(W, H, n);
        Context ctx(fb);
        count_coverage(ctx);
        draw(ctx, ConstantColorShader{glm::vec4(16 / 255.0f, 0, 0, 1)}, v, idx);
        // each sample: covered by as many triangles as the independent test says, at most one
        // where the fan does not fold over itself: check the sum against the test.
        const auto p = [&](uint32_t i) {
            const glm::vec4 c = v[i].clip;
            return glm::dvec2(std::round((c.x / c.w + 1) * W / 2 * 256) / 256, std::round((1 - c.y / c.w) * H / 2 * 256) / 256);
        };
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                for (int s = 0; s < n; ++s) {
                    int count = 0;
                    for (size_t t = 0; t < idx.size(); t += 3)
                        count += inside(p(idx[t]), p(idx[t + 1]), p(idx[t + 2]), glm::dvec2(x, y) + d3d_position(n, s));
                    ASSERT_EQ(fb.color_data()[fb.sample_index(x, y, s)].r, std::min(255, 16 * count));
                }
    }
}

TEST_P(SamplePatterns, FlatSceneResolvesToCoverageFraction) {
    const int n = GetParam();
    std::mt19937 rng(7 + unsigned(n));
    for (int trial = 0; trial < 30; ++trial) {
        const glm::dvec2 a = random_point(rng), b = random_point(rng), c = random_point(rng);
        const Framebuffer fb = white_triangle(n, a, b, c);
        const Image img = fb.read_pixels();
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int k = 0;
                for (int s = 0; s < n; ++s) k += inside(a, b, c, glm::dvec2(x, y) + d3d_position(n, s));
                ASSERT_EQ(img.at(x, y).r, int(std::floor(255.0 * k / n + 0.5))) << x << "," << y;
            }
    }
}

INSTANTIATE_TEST_SUITE_P(Counts, SamplePatterns, ::testing::Values(2, 4, 8, 16));

// Triangles a few pixels across, as a mesh finer than the pixels has, at every sample count
// and through either command (stencil off, or on and always passing): each sample covered
// exactly when inside. Binning bounds a triangle by the framebuffer's own pattern and drops
// a single-sampled one that covers no pixel center; a pattern narrower than the
// framebuffer's would lose samples here.
TEST(SamplePatternsAnyCount, TinyTrianglesCoveredExactlyWhenInside) {
    std::mt19937 rng(77);
    std::uniform_int_distribution<int> step(-3 * 256, 3 * 256), small_step(-64, 64);  // up to 3 pixels, or a quarter
    for (const int n : {1, 2, 4, 8, 16})
        for (const bool stencil : {false, true}) {
            int covered_total = 0;
            for (int trial = 0; trial < 400; ++trial) {
                auto offset = [&] { return trial % 2 ? glm::dvec2(step(rng), step(rng)) / 256.0 : glm::dvec2(small_step(rng), small_step(rng)) / 256.0; };
                const glm::dvec2 a = random_point(rng), b = a + offset(), c = a + offset();
                const Framebuffer fb = white_triangle(n, a, b, c, stencil);
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x)
                        for (int s = 0; s < n; ++s) {
                            const glm::dvec2 at = glm::dvec2(x, y) + (n == 1 ? glm::dvec2(0.5, 0.5) : d3d_position(n, s));
                            const bool got = fb.color_data()[fb.sample_index(x, y, s)].r == 255;
                            covered_total += got;
                            ASSERT_EQ(got, inside(a, b, c, at)) << "samples " << n << (stencil ? " stencil" : "") << " trial " << trial << " pixel "
                                                                << x << "," << y << " sample " << s;
                        }
            }
            EXPECT_GT(covered_total, 20 * n) << "samples " << n;
        }
}

// The pixels a triangle's samples may fall in (pixel_bounds), against the formula worked
// out here in 64-bit integers: from ceil((m - hi) / 256) to floor((M - lo) / 256) across and
// down, for every sample count's extent, corners anywhere in the guard band or a few pixels
// apart, in every order, and all three at one point.
TEST(PixelBounds, MatchTheirFormula) {
    auto floor_div = [](int64_t v) { return v >= 0 ? v / 256 : -((-v + 255) / 256); };
    std::mt19937 rng(5);
    const int32_t reach = (65536 + 8192) * 256;  // the guard band's corner, in 1/256 pixel
    std::uniform_int_distribution<int32_t> anywhere(-reach, reach), close(-1024, 1024);
    const SampleExtent extents[] = {sample_extent<1>(), sample_extent<2>(), sample_extent<4>(), sample_extent<8>(), sample_extent<16>()};
    for (const SampleExtent& s : extents)
        for (int trial = 0; trial < 20000; ++trial) {
            ShadedVertex<1> v[3];
            const int32_t x = anywhere(rng), y = anywhere(rng);
            for (ShadedVertex<1>& c : v) {
                c.X = trial % 2 ? anywhere(rng) : x + close(rng), c.Y = trial % 2 ? anywhere(rng) : y + close(rng);
                if (trial % 7 == 0) c.X = x, c.Y = y;
            }
            const int64_t mx = std::min({v[0].X, v[1].X, v[2].X}), my = std::min({v[0].Y, v[1].Y, v[2].Y});
            const int64_t Mx = std::max({v[0].X, v[1].X, v[2].X}), My = std::max({v[0].Y, v[1].Y, v[2].Y});
            const Rect want{int(floor_div(mx - s.x_hi + 255)), int(floor_div(my - s.y_hi + 255)), int(floor_div(Mx - s.x_lo) + 1), int(floor_div(My - s.y_lo) + 1)};
            for (const auto& [i, j, k] : {std::array{0, 1, 2}, std::array{1, 2, 0}, std::array{2, 0, 1}, std::array{0, 2, 1}}) {
                const Rect got = pixel_bounds(v[i], v[j], v[k], s);
                ASSERT_TRUE(got.x0 == want.x0 && got.y0 == want.y0 && got.x1 == want.x1 && got.y1 == want.y1)
                    << "extent " << s.x_lo << ".." << s.x_hi << " trial " << trial << ": " << got.x0 << "," << got.y0 << " " << got.x1 << ","
                    << got.y1 << " want " << want.x0 << "," << want.y0 << " " << want.x1 << "," << want.y1;
            }
        }
}
