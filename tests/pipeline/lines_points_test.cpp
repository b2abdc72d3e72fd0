// Lines (the diamond-exit rule, wide lines, multisampled rectangles), points (squares),
// their clipping, and flat varyings with the provoking vertex.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <set>

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

namespace {
// The pixels a line from (x0, y0) to (x1, y1) lights, in a W x H picture.
std::vector<int> line_pixels(float x0, float y0, float x1, float y1, float width = 1.0f) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.line_width = width;
    draw(ctx, ConstantColorShader{}, {{window_to_clip(x0, y0, W, H), 0}, {window_to_clip(x1, y1, W, H), 0}}, {0, 1}, Topology::Lines);
    return lit(fb);
}
}  // namespace

// The first endpoint's pixel is drawn when the segment crosses its diamond, even from past
// the pixel's center; the last endpoint's is drawn only when the segment leaves its diamond.
TEST(Lines, DiamondExitAtTheEnds) {
    const int row = 3 * W;
    EXPECT_EQ(line_pixels(2.7f, 3.5f, 7.5f, 3.5f), (std::vector<int>{row + 2, row + 3, row + 4, row + 5, row + 6}));
    EXPECT_EQ(line_pixels(2.5f, 3.5f, 7.9f, 3.5f), (std::vector<int>{row + 2, row + 3, row + 4, row + 5, row + 6}));
    EXPECT_EQ(line_pixels(2.5f, 3.5f, 8.05f, 3.5f), (std::vector<int>{row + 2, row + 3, row + 4, row + 5, row + 6, row + 7}));
    // starting outside its pixel's diamond, heading away from it: not drawn
    EXPECT_EQ(line_pixels(2.95f, 3.1f, 7.5f, 3.3f), (std::vector<int>{row + 3, row + 4, row + 5, row + 6}));
    // the same going left: the rule follows the direction
    EXPECT_EQ(line_pixels(7.5f, 3.5f, 2.7f, 3.5f), (std::vector<int>{row + 3, row + 4, row + 5, row + 6, row + 7}));
}

// A strip of segments lights the shared endpoint once: drawn additively, no pixel is doubled.
TEST(Lines, StripDrawsSharedEndpointsOnce) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    count_coverage(ctx);
    // (x-major segments: the rule keeps two segments of the same major axis from both drawing
    // their shared endpoint's pixel)
    const std::vector<ClipVertexIn> v = {{window_to_clip(1.3f, 2.2f, W, H), 0}, {window_to_clip(6.62f, 4.23f, W, H), 0},
                                         {window_to_clip(11.2f, 6.7f, W, H), 0}, {window_to_clip(14.1f, 5.4f, W, H), 0}};
    draw(ctx, ConstantColorShader{glm::vec4(0.25f, 0, 0, 1)}, v, {0, 1, 1, 2, 2, 3}, Topology::Lines);
    int drawn = 0;
    for (int i = 0; i < W * H; ++i) {
        EXPECT_LE(fb.color_data()[i].r, 64) << "pixel " << i;
        drawn += fb.color_data()[i].r > 0;
    }
    EXPECT_GT(drawn, 11);
}

TEST(Lines, WideLinesCoverWidthPixelsAcrossTheMinorAxis) {
    // x-major: three rows; y-major: three columns
    EXPECT_EQ(line_pixels(2.5f, 5.5f, 5.5f, 5.5f, 3.0f), (std::vector<int>{4 * W + 2, 4 * W + 3, 4 * W + 4, 5 * W + 2, 5 * W + 3,
                                                                            5 * W + 4, 6 * W + 2, 6 * W + 3, 6 * W + 4}));
    EXPECT_EQ(line_pixels(8.5f, 2.5f, 8.5f, 4.5f, 3.0f), (std::vector<int>{2 * W + 7, 2 * W + 8, 2 * W + 9, 3 * W + 7, 3 * W + 8, 3 * W + 9}));
    // width 2: the two pixels whose centers are within 1 of the line
    EXPECT_EQ(line_pixels(2.5f, 6.2f, 4.5f, 6.2f, 2.0f), (std::vector<int>{5 * W + 2, 5 * W + 3, 6 * W + 2, 6 * W + 3}));
}

// With 4 samples a line is a rectangle: a 1-wide horizontal one over a pixel row from x = 2 to
// x = 6 covers every sample of pixels 2..5 of that row and nothing else.
TEST(Lines, MultisampledLinesAreRectangles) {
    Framebuffer fb(W, H, 4);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    draw(ctx, ConstantColorShader{}, {{window_to_clip(2.0f, 4.5f, W, H), 0}, {window_to_clip(6.0f, 4.5f, W, H), 0}}, {0, 1},
         Topology::Lines);
    const Image img = fb.read_pixels();
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) EXPECT_EQ(img.at(x, y).r, y == 4 && x >= 2 && x < 6 ? 255 : 0) << x << "," << y;
    // A wide one at a slant: each sample is covered exactly when it lies inside the rectangle
    // (but for those within the snapping of its corners to 1/256 pixel of its border).
    const glm::vec2 a(2.3f, 3.1f), b(12.6f, 9.4f);
    const float width = 2.6f;
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.line_width = width;
    draw(ctx, ConstantColorShader{}, {{window_to_clip(a.x, a.y, W, H), 0}, {window_to_clip(b.x, b.y, W, H), 0}}, {0, 1},
         Topology::Lines);
    const glm::vec2 along = glm::normalize(b - a), across(-along.y, along.x);
    int covered = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int s = 0; s < 4; ++s) {
                const glm::vec2 p(x + SamplePattern<4>::x[size_t(s)] / 256.0f, y + SamplePattern<4>::y[size_t(s)] / 256.0f);
                const float u = glm::dot(p - a, along), v = glm::dot(p - a, across);
                const float len = glm::length(b - a), snap = 2.0f / 256.0f;
                if (std::fabs(u) < snap || std::fabs(u - len) < snap || std::fabs(std::fabs(v) - width / 2) < snap) continue;
                const bool inside = u > 0 && u < len && std::fabs(v) < width / 2;
                EXPECT_EQ(fb.color_data()[fb.sample_index(x, y) + size_t(s)].r > 0, inside) << x << "," << y << " sample " << s;
                covered += inside;
            }
    EXPECT_GT(covered, 100);
}

TEST(Points, SquaresOfTheirSize) {
    auto points = [](float x, float y, float size) {
        Framebuffer fb(W, H);
        Context ctx(fb);
        ctx.clear(glm::vec4(0, 0, 0, 1));
        ctx.state.point_size = size;
        draw(ctx, ConstantColorShader{}, {{window_to_clip(x, y, W, H), 0}}, {0}, Topology::Points);
        return lit(fb);
    };
    EXPECT_EQ(points(5.5f, 5.5f, 3.0f), (std::vector<int>{4 * W + 4, 4 * W + 5, 4 * W + 6, 5 * W + 4, 5 * W + 5, 5 * W + 6,
                                                         6 * W + 4, 6 * W + 5, 6 * W + 6}));
    EXPECT_EQ(points(5.0f, 5.0f, 2.0f), (std::vector<int>{4 * W + 4, 4 * W + 5, 5 * W + 4, 5 * W + 5}));
    EXPECT_EQ(points(5.2f, 6.7f, 1.0f), (std::vector<int>{6 * W + 5}));
    EXPECT_EQ(points(5.2f, 6.7f, 0.5f), (std::vector<int>{6 * W + 5}));  // at least one pixel
}

namespace {
// Flat color: the provoking vertex's, not interpolated.
struct FlatColorShader {
    using Vertex = RgbVertex;
    using Varyings = RgbVaryings;
    static constexpr uint64_t kFlat = varying_bits(0, sizeof(RgbVaryings));
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out = {in.color.r, in.color.g, in.color.b};
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord&, glm::vec4& c) const {
        c = glm::vec4(v.r, v.g, v.b, 1.0f);
        return true;
    }
};

// The distinct colors of a picture's pixels that are not black.
std::set<std::array<uint8_t, 3>> colors_drawn(const Framebuffer& fb) {
    std::set<std::array<uint8_t, 3>> out;
    for (int i = 0; i < fb.width() * fb.height(); ++i) {
        const Rgba8 c = fb.color_data()[i];
        if (c.r || c.g || c.b) out.insert({c.r, c.g, c.b});
    }
    return out;
}
}  // namespace

TEST(FlatVaryings, TakeTheProvokingVertexOfTrianglesAndLines) {
    const std::vector<RgbVertex> v = {{window_to_clip(1, 1, W, H), {1, 0, 0}},
                                      {window_to_clip(15, 2, W, H), {0, 1, 0}},
                                      {window_to_clip(3, 14, W, H), {0, 0, 1}}};
    for (const ProvokingVertex pv : {ProvokingVertex::Last, ProvokingVertex::First}) {
        const std::array<uint8_t, 3> expected = pv == ProvokingVertex::Last ? std::array<uint8_t, 3>{0, 0, 255}
                                                                            : std::array<uint8_t, 3>{255, 0, 0};
        for (const Topology t : {Topology::Triangles, Topology::Lines}) {
            Framebuffer fb(W, H);
            Context ctx(fb);
            ctx.clear(glm::vec4(0, 0, 0, 1));
            ctx.state.cull = CullMode::None;
            ctx.state.provoking_vertex = pv;
            const std::vector<uint32_t> idx = t == Topology::Triangles ? std::vector<uint32_t>{0, 1, 2} : std::vector<uint32_t>{0, 2};
            draw(ctx, FlatColorShader{}, v, idx, t);
            EXPECT_EQ(colors_drawn(fb), (std::set<std::array<uint8_t, 3>>{expected}));
        }
    }
}

// A triangle cut by the near plane is drawn as several; all keep the provoking vertex's value.
TEST(FlatVaryings, SurviveClipping) {
    std::vector<RgbVertex> v = {{window_to_clip(1, 1, W, H, 0.5f), {1, 0, 0}},
                                {window_to_clip(15, 2, W, H, 0.5f), {0, 1, 0}},
                                {glm::vec4(0.0f, -0.5f, -2.0f, 1.0f), {0, 0, 1}}};  // in front of the near plane
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    draw(ctx, FlatColorShader{}, v, {0, 1, 2});
    EXPECT_EQ(colors_drawn(fb), (std::set<std::array<uint8_t, 3>>{{0, 0, 255}}));
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.provoking_vertex = ProvokingVertex::First;
    draw(ctx, FlatColorShader{}, v, {0, 1, 2});
    EXPECT_EQ(colors_drawn(fb), (std::set<std::array<uint8_t, 3>>{{255, 0, 0}}));
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
    // In a long buffer (the vectorized part of the check, not its tail): one past the end,
    // the largest index, and none.
    std::vector<uint32_t> idx(300, 0);
    idx[151] = 1;
    EXPECT_THROW(draw(ctx, ConstantColorShader{}, v, idx), std::out_of_range);
    idx[151] = UINT32_MAX;
    EXPECT_THROW(draw(ctx, ConstantColorShader{}, v, idx), std::out_of_range);
    idx[151] = 0;
    EXPECT_NO_THROW(draw(ctx, ConstantColorShader{}, v, idx));
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
