// Lines (DDA, half-open) and points, with clipping.
#include <gtest/gtest.h>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {
constexpr int W = 16, H = 16;

std::vector<int> lit(const Framebuffer& fb) {
    std::vector<int> out;
    for (int i = 0; i < W * H; ++i)
        if (fb.color_data()[i].r) out.push_back(i);
    return out;
}
}  // namespace

TEST(Lines, HorizontalAndDiagonal) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    std::vector<ClipVertexIn> v = {{window_to_clip(2.5f, 3.5f, W, H), 0}, {window_to_clip(7.5f, 3.5f, W, H), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1}, Topology::Lines);
    EXPECT_EQ(lit(fb), (std::vector<int>{3 * W + 2, 3 * W + 3, 3 * W + 4, 3 * W + 5, 3 * W + 6}));  // [p0, p1)

    ctx.clear(glm::vec4(0, 0, 0, 1));
    v = {{window_to_clip(0.5f, 0.5f, W, H), 0}, {window_to_clip(4.5f, 4.5f, W, H), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1}, Topology::Lines);
    EXPECT_EQ(lit(fb), (std::vector<int>{0, W + 1, 2 * W + 2, 3 * W + 3}));
}

TEST(Lines, ClippedAtTheViewport) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    std::vector<ClipVertexIn> v = {{window_to_clip(-40, 8.5f, W, H), 0}, {window_to_clip(60, 8.5f, W, H), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1}, Topology::Lines);
    EXPECT_EQ(lit(fb).size(), size_t(W));
}

TEST(Points, OnePixelEachAndOutsideDropped) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    std::vector<ClipVertexIn> v = {{window_to_clip(5.2f, 6.7f, W, H), 0}, {window_to_clip(30, 3, W, H), 0},
                                   {glm::vec4(0, 0, 0, -1), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1, 2}, Topology::Points);
    EXPECT_EQ(lit(fb), (std::vector<int>{6 * W + 5}));
}

TEST(PrimitiveAssembly, IndexOutOfRangeThrows) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    std::vector<ClipVertexIn> v = {{glm::vec4(0, 0, 0, 1), 0}};
    EXPECT_THROW(draw(ctx, ConstantColorShader{}, v, {0, 0, 1}), std::out_of_range);
}

TEST(PrimitiveAssembly, NonFinitePositionsDropOnlyTheirTriangles) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H), 0},  {window_to_clip(8, 0, W, H), 0},
                                   {window_to_clip(0, 8, W, H), 0},  {glm::vec4(NAN, 0, 0, 1), 0},
                                   {glm::vec4(INFINITY, 1, 0, 1), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1, 2, 0, 3, 1, 4, 1, 2});
    EXPECT_EQ(fb.color_data()[fb.sample_index(1, 1)].r, 255);
    EXPECT_EQ(fb.color_data()[fb.sample_index(12, 12)].r, 0);
}
