// Culling: windings as they appear on screen, each cull mode and front-face convention,
// and zero-area triangles, which are never drawn.
#include <cstdlib>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 16, H = 16;

struct FacingShader : ConstantColorShader {
    bool fragment(const Varyings&, const FragCoord& f, glm::vec4& c) const {
        c = f.front_facing ? glm::vec4(0, 1, 0, 1) : glm::vec4(1, 0, 0, 1);
        return true;
    }
};

// 0 = not drawn, 1 = drawn as front face, 2 = drawn as back face.
int draw_winding(bool ccw_on_screen, CullMode cull, FrontFace front) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = cull;
    ctx.state.front_face = front;
    // On screen (y down): (2,2) -> (14,2) -> (2,14) turns clockwise.
    std::vector<ClipVertexIn> v = {{window_to_clip(2, 2, W, H), 0}, {window_to_clip(14, 2, W, H), 0},
                                   {window_to_clip(2, 14, W, H), 0}};
    draw(ctx, FacingShader{}, v, ccw_on_screen ? std::vector<uint32_t>{0, 2, 1} : std::vector<uint32_t>{0, 1, 2});
    const Rgba8 c = fb.color_data()[fb.sample_index(4, 4)];
    return c.g == 255 ? 1 : c.r == 255 ? 2 : 0;
}

}  // namespace

TEST(Culling, WindingsAndModes) {
    // CCW front (OpenGL default).
    EXPECT_EQ(draw_winding(true, CullMode::Back, FrontFace::CCW), 1);
    EXPECT_EQ(draw_winding(false, CullMode::Back, FrontFace::CCW), 0);
    EXPECT_EQ(draw_winding(true, CullMode::Front, FrontFace::CCW), 0);
    EXPECT_EQ(draw_winding(false, CullMode::Front, FrontFace::CCW), 2);
    EXPECT_EQ(draw_winding(true, CullMode::None, FrontFace::CCW), 1);
    EXPECT_EQ(draw_winding(false, CullMode::None, FrontFace::CCW), 2);
    // CW front.
    EXPECT_EQ(draw_winding(false, CullMode::Back, FrontFace::CW), 1);
    EXPECT_EQ(draw_winding(true, CullMode::Back, FrontFace::CW), 0);
    EXPECT_EQ(draw_winding(true, CullMode::None, FrontFace::CW), 2);
}

TEST(Culling, ZeroAreaTrianglesAreNeverDrawn) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    // Collinear, and a triangle whose corners differ by less than the 1/256 pixel snapping,
    // both on the diagonal; in the same draw a real triangle off it, in the upper right,
    // which must be drawn (so the draw itself ran).
    std::vector<ClipVertexIn> v = {{window_to_clip(1, 1, W, H), 0},     {window_to_clip(8, 8, W, H), 0},
                                   {window_to_clip(15, 15, W, H), 0},   {window_to_clip(4.5f, 4.5f, W, H), 0},
                                   {window_to_clip(4.501f, 4.5f, W, H), 0}, {window_to_clip(4.5f, 4.501f, W, H), 0},
                                   {window_to_clip(9, 1, W, H), 0},     {window_to_clip(15, 1, W, H), 0},
                                   {window_to_clip(15, 7, W, H), 0}};
    draw(ctx, ConstantColorShader{}, v, {0, 1, 2, 3, 4, 5, 6, 7, 8});
    int lit = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const bool on = fb.color_data()[y * W + x].r != 0;
            if (std::abs(x - y) <= 2) {
                ASSERT_FALSE(on) << x << ", " << y;
            }
            if (on) {
                EXPECT_TRUE(x >= 9 && y < 7) << x << ", " << y;
            }
            lit += on;
        }
    EXPECT_EQ(lit, 6 + 5 + 4 + 3 + 2 + 1);  // the real triangle's pixel centers, top-left rule
}
