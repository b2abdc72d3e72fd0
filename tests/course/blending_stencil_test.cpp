// Lesson 13 (course/13-blending-stencil): the pipeline blends as the lesson's formulas say
// (alpha "over" depends on the order, additive does not), and a draw that tests the stencil
// against a mark made by another draw covers exactly the pixels both cover.
#include <gtest/gtest.h>

#include <random>

#include "course/13-blending-stencil/blend.h"
#include "course/common/pipeline.h"

using namespace course;

namespace {

constexpr int kSize = 32;

// Full-picture layers of flat colors blended in order onto black, by the pipeline.
softraster::Image layers(const std::vector<glm::vec4>& colors, softraster::BlendMode blend) {
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = softraster::CullMode::None;
    ctx.state.depth_test = false;
    ctx.state.blend = blend;
    const std::vector<MeshIn> quad = {{{-1, -1, 0}, {0, 0, 1}, {}}, {{1, -1, 0}, {0, 0, 1}, {}}, {{1, 1, 0}, {0, 0, 1}, {}}, {{-1, 1, 0}, {0, 0, 1}, {}}};
    const uint32_t indices[] = {0, 1, 2, 0, 2, 3};
    for (const glm::vec4& c : colors)
        ctx.draw(softraster::Topology::Triangles, FlatShader{glm::mat4(1.0f), glm::mat4(1.0f), c}, std::span<const MeshIn>(quad),
                 std::span<const uint32_t>(indices));
    return ctx.read_pixels();
}

}  // namespace

TEST(CourseBlending, OverAndAdditiveAsTheFormulasSay) {
    std::mt19937 rng(18);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int order_mattered = 0;
    for (int n = 0; n < 200; ++n) {
        // (Colors of 8 bits, as the framebuffer stores them and the blender reads the fragment.)
        const glm::vec4 a = glm::round(glm::vec4(u(rng), u(rng), u(rng), u(rng)) * 255.0f) / 255.0f,
                        b = glm::round(glm::vec4(u(rng), u(rng), u(rng), u(rng)) * 255.0f) / 255.0f;
        const softraster::Image ab = layers({a, b}, softraster::BlendMode::Alpha), ba = layers({b, a}, softraster::BlendMode::Alpha);
        // (The framebuffer holds 8 bits: the first layer's result is rounded before the second.)
        const glm::vec3 want = blend_over(b, glm::round(blend_over(a, glm::vec3(0.0f)) * 255.0f) / 255.0f);
        const softraster::Rgba8 got = ab.at(5, 7);
        EXPECT_NEAR(got.r / 255.0f, want.r, 1.01f / 255.0f);
        EXPECT_NEAR(got.g / 255.0f, want.g, 1.01f / 255.0f);
        EXPECT_NEAR(got.b / 255.0f, want.b, 1.01f / 255.0f);
        order_mattered += !(ab.pixels == ba.pixels);
        const softraster::Image sum1 = layers({a, b}, softraster::BlendMode::Additive), sum2 = layers({b, a}, softraster::BlendMode::Additive);
        const glm::vec3 added = blend_additive(b, glm::round(blend_additive(a, glm::vec3(0.0f)) * 255.0f) / 255.0f);
        EXPECT_NEAR(sum1.at(3, 3).g / 255.0f, added.g, 1.01f / 255.0f);
        EXPECT_EQ(sum1.pixels, sum2.pixels) << n;  // the same in either order
    }
    EXPECT_GT(order_mattered, 150);
}

TEST(CourseStencil, AMarkCutsTheNextDrawToItsPixels) {
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> coord(0.0f, float(kSize));
    for (int n = 0; n < 300; ++n) {
        PixelVertex mask[3], shape[3];
        for (PixelVertex& p : mask) p = {{coord(rng), coord(rng)}};
        for (PixelVertex& p : shape) p = {{coord(rng), coord(rng)}};
        softraster::Framebuffer fb(kSize, kSize);
        softraster::Context ctx(fb);
        ctx.clear(glm::vec4(0, 0, 0, 1));
        ctx.state.cull = softraster::CullMode::None;
        ctx.state.depth_test = false;
        const uint32_t indices[] = {0, 1, 2};
        const PixelShader shader{float(kSize), float(kSize)};
        ctx.state.color_write = false;
        ctx.state.stencil_test = true;
        ctx.state.stencil_front = ctx.state.stencil_back = {softraster::CompareFunc::Always, 1, 0xff, 0xff, softraster::StencilOp::Keep,
                                                            softraster::StencilOp::Keep, softraster::StencilOp::Replace};
        ctx.draw(softraster::Topology::Triangles, shader, std::span<const PixelVertex>(mask), std::span<const uint32_t>(indices));
        ctx.state.color_write = true;
        ctx.state.stencil_front = ctx.state.stencil_back = {softraster::CompareFunc::Equal, 1, 0xff, 0xff, softraster::StencilOp::Keep,
                                                            softraster::StencilOp::Keep, softraster::StencilOp::Keep};
        ctx.draw(softraster::Topology::Triangles, shader, std::span<const PixelVertex>(shape), std::span<const uint32_t>(indices));
        const softraster::Image picture = ctx.read_pixels();
        const std::vector<bool> in_mask = pipeline_coverage(kSize, kSize, softraster::Topology::Triangles, mask);
        const std::vector<bool> in_shape = pipeline_coverage(kSize, kSize, softraster::Topology::Triangles, shape);
        for (int i = 0; i < kSize * kSize; ++i)
            ASSERT_EQ(picture.pixels[size_t(i)].r != 0, in_mask[size_t(i)] && in_shape[size_t(i)] && stencil_equal_passes(1, 1)) << n << " pixel " << i;
    }
}
