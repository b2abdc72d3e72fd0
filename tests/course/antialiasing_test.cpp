// Lesson 14 (course/14-antialiasing): a pixel's color under 4x MSAA is the share of the
// rotated grid's four sample points the triangle covers, and under 2 x 2 supersampling the
// share of the four sub-pixel centers (lesson 3's edge functions at those points), on random
// triangles drawn by the pipeline.
#include <gtest/gtest.h>

#include <random>

#include "course/14-antialiasing/coverage.h"
#include "course/common/pipeline.h"
#include "softraster/pipeline/resolve.h"

using namespace course;

namespace {

constexpr int kSize = 32;

softraster::Image draw_white(const Point (&t)[3], int scale, int samples) {
    softraster::Framebuffer fb(kSize * scale, kSize * scale, samples);
    softraster::Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = softraster::CullMode::None;
    PixelVertex v[3];
    for (int k = 0; k < 3; ++k) v[k] = {{float(t[k].x * scale) / kSub, float(t[k].y * scale) / kSub}};
    const uint32_t indices[] = {0, 1, 2};
    ctx.draw(softraster::Topology::Triangles, PixelShader{float(kSize * scale), float(kSize * scale)}, std::span<const PixelVertex>(v),
             std::span<const uint32_t>(indices));
    return ctx.read_pixels();
}

}  // namespace

TEST(CourseAntialiasing, PixelsAreTheShareOfSamplesCovered) {
    std::mt19937 rng(20);
    std::uniform_int_distribution<int64_t> coord(0, kSize * kSub - 1);
    int partial = 0;
    for (int n = 0; n < 300; ++n) {
        const Point t[3] = {{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        const softraster::Image msaa = draw_white(t, 1, 4);
        const softraster::Image ssaa = softraster::downsample_box(draw_white(t, 2, 1), 2);
        for (int j = 0; j < kSize; ++j)
            for (int i = 0; i < kSize; ++i) {
                const int m = covered_samples(t[0], t[1], t[2], i, j, kRotatedGrid), s = covered_samples(t[0], t[1], t[2], i, j, kOrderedGrid);
                ASSERT_NEAR(msaa.at(i, j).r, 255.0 * m / 4.0, 0.51) << n << " pixel " << i << "," << j;
                ASSERT_NEAR(ssaa.at(i, j).r, 255.0 * s / 4.0, 0.51) << n << " pixel " << i << "," << j;
                partial += m % 4 != 0;
            }
    }
    EXPECT_GT(partial, 1000);  // (edges did cross pixels)
}
