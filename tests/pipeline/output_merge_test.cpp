// Output merge: every depth compare function, depth writes on and off, and the blend modes.
#include <gtest/gtest.h>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 8, H = 8;

// Draws a full-screen quad at depth z over a buffer cleared to depth `stored`; returns
// whether the center pixel was written and the depth left there.
std::pair<bool, float> draw_at(DepthFunc f, float z, float stored, bool write = true) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1), stored);
    ctx.state.depth_func = f;
    ctx.state.depth_write = write;
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H, z), 0}, {window_to_clip(W, 0, W, H, z), 0},
                                   {window_to_clip(W, H, W, H, z), 0}, {window_to_clip(0, H, W, H, z), 0}};
    ctx.state.cull = CullMode::None;
    draw(ctx, ConstantColorShader{glm::vec4(1, 0, 0, 1)}, v, {0, 1, 2, 0, 2, 3});
    const size_t i = fb.sample_index(4, 4);
    return {fb.color_data()[i].r == 255, fb.depth_data()[i]};
}

}  // namespace

TEST(DepthTest, EveryCompareFunction) {
    struct Case {
        DepthFunc f;
        bool less, equal, greater;  // passes when z < stored, z == stored, z > stored
    };
    const Case cases[] = {
        {DepthFunc::Never, false, false, false},     {DepthFunc::Less, true, false, false},
        {DepthFunc::Equal, false, true, false},      {DepthFunc::LessEqual, true, true, false},
        {DepthFunc::Greater, false, false, true},    {DepthFunc::NotEqual, true, false, true},
        {DepthFunc::GreaterEqual, false, true, true}, {DepthFunc::Always, true, true, true},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(draw_at(c.f, 0.25f, 0.5f).first, c.less) << int(c.f);
        EXPECT_EQ(draw_at(c.f, 0.5f, 0.5f).first, c.equal) << int(c.f);
        EXPECT_EQ(draw_at(c.f, 0.75f, 0.5f).first, c.greater) << int(c.f);
    }
}

TEST(DepthTest, WritesOnlyWhenEnabledAndPassing) {
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.25f, 0.5f, true).second, 0.25f);
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.25f, 0.5f, false).second, 0.5f);
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.75f, 0.5f, true).second, 0.5f);
}

TEST(Blend, AlphaAndAdditiveFollowTheFormulas) {
    const Rgba8 dst{100, 200, 50, 128};
    const glm::vec4 src(0.8f, 0.2f, 0.4f, 0.25f);
    const Rgba8 a = blend<BlendMode::Alpha>(src, dst);
    EXPECT_EQ(a.r, quantize_unorm8(0.8f * 0.25f + 100 / 255.0f * 0.75f));
    EXPECT_EQ(a.g, quantize_unorm8(0.2f * 0.25f + 200 / 255.0f * 0.75f));
    EXPECT_EQ(a.a, quantize_unorm8(0.25f + 128 / 255.0f * 0.75f));
    const Rgba8 add = blend<BlendMode::Additive>(src, dst);
    EXPECT_EQ(add.r, quantize_unorm8(0.8f * 0.25f + 100 / 255.0f));
    EXPECT_EQ(add.g, 213);  // 0.05 + 200/255 -> 212.75 -> 213
    EXPECT_EQ(add.a, 128);  // additive keeps the destination alpha
    EXPECT_EQ(blend<BlendMode::Additive>(glm::vec4(1, 1, 1, 1), Rgba8{250, 250, 250, 255}).r, 255);  // saturates
    EXPECT_EQ(blend<BlendMode::Opaque>(glm::vec4(2, -1, 0.5f, 1), dst), (Rgba8{255, 0, 128, 255}));
}

TEST(Quantize, RoundsHalfUpAndClamps) {
    EXPECT_EQ(quantize_unorm8(0.5f), 128);  // floor(127.5 + 0.5)
    EXPECT_EQ(quantize_unorm8(-0.1f), 0);
    EXPECT_EQ(quantize_unorm8(1.7f), 255);
    EXPECT_EQ(quantize_unorm8(NAN), 0);
    EXPECT_EQ(quantize_unorm8(1.0f / 255.0f), 1);
}
