// 4x MSAA: per-sample coverage at the spec's positions, one shader run per pixel, the color
// on every covered sample, and the resolve floor(mean + 0.5).
#include <gtest/gtest.h>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

struct CountingShader : ConstantColorShader {
    int* runs;
    bool fragment(const Varyings& v, const FragCoord& f, glm::vec4& c) const {
        ++*runs;
        return ConstantColorShader::fragment(v, f, c);
    }
};

}  // namespace

TEST(Msaa, CoverageFollowsSamplePositions) {
    constexpr int W = 4, H = 4;
    // A rectangle whose left edge is at x = 1.5: in pixel 1, samples at x offsets 0.875 and
    // 0.625 (samples 1 and 3) are inside, 0.375 and 0.125 (samples 0 and 2) are not.
    Framebuffer fb(W, H, 4);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    int runs = 0;
    // One big triangle whose only edge inside the picture is x = 1.5.
    std::vector<ClipVertexIn> v = {{window_to_clip(1.5f, -20, W, H), 0}, {window_to_clip(30, 4, W, H), 0},
                                   {window_to_clip(1.5f, 30, W, H), 0}};
    CountingShader s;
    s.color = glm::vec4(1, 1, 1, 1);
    s.runs = &runs;
    draw(ctx, s, v, {0, 1, 2});
    EXPECT_EQ(runs, 3 * H);  // once per pixel with coverage: columns 1, 2, 3
    for (int y = 0; y < H; ++y) {
        const Rgba8* px = &fb.color_data()[fb.sample_index(1, y)];
        EXPECT_EQ(px[0].r, 0);
        EXPECT_EQ(px[1].r, 255);
        EXPECT_EQ(px[2].r, 0);
        EXPECT_EQ(px[3].r, 255);
    }
    const Image img = fb.read_pixels();
    EXPECT_EQ(img.at(0, 0).r, 0);
    EXPECT_EQ(img.at(1, 0).r, 128);  // floor((0 + 255 + 0 + 255) / 4 + 0.5) = 128
    EXPECT_EQ(img.at(2, 0).r, 255);
}

TEST(Msaa, PerSampleDepth) {
    // A steep depth ramp across one pixel: each sample is tested at its own depth.
    constexpr int W = 1, H = 1;
    Framebuffer fb(W, H, 4);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1), 0.5f);
    ctx.state.cull = CullMode::None;
    // depth = x across the pixel: 0 at x = 0, 1 at x = 1.
    std::vector<ClipVertexIn> v = {{window_to_clip(0, -10, W, H, 0.0f), 0}, {window_to_clip(1, -10, W, H, 1.0f), 0},
                                   {window_to_clip(1, 10, W, H, 1.0f), 0}, {window_to_clip(0, 10, W, H, 0.0f), 0}};
    draw(ctx, ConstantColorShader{glm::vec4(1)}, v, {0, 1, 2, 0, 2, 3});
    const Rgba8* px = fb.color_data();
    EXPECT_EQ(px[0].r, 255);  // x = 0.375 < 0.5
    EXPECT_EQ(px[1].r, 0);    // x = 0.875
    EXPECT_EQ(px[2].r, 255);  // x = 0.125
    EXPECT_EQ(px[3].r, 0);    // x = 0.625
    EXPECT_NEAR(fb.depth_data()[0], 0.375f, 1e-6f);
    EXPECT_NEAR(fb.depth_data()[1], 0.5f, 1e-6f);
}
