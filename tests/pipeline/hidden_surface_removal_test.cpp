// Hidden-surface removal must not change the picture: random overlapping opaque draws
// rendered with a pure shader (two-pass path) and with the same shader marked impure
// (ordinary path) give byte-identical color and depth, with and without MSAA, for depth
// functions that keep the nearer, the farther, or ties.
#include <gtest/gtest.h>

#include <random>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

// Twelve random overlapping quads at repeated depths (ties), each with a slanted triangle
// that cuts through the others: one draw each.
std::vector<RgbMesh> layers() {
    constexpr int W = 150, H = 100;
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<RgbMesh> out;
    for (int l = 0; l < 12; ++l) {
        RgbMesh m;
        m.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
        const float z = float(l % 5) * 0.1f + 0.2f;
        const float x0 = u(rng) * W * 0.5f - 10, y0 = u(rng) * H * 0.5f - 10, x1 = x0 + 40 + u(rng) * W, y1 = y0 + 30 + u(rng) * H;
        for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y1)})
            m.vertices.push_back({window_to_clip(p.x, p.y, W, H, z + 0.05f * u(rng), 1.0f + u(rng)), glm::vec3(u(rng), u(rng), u(rng))});
        for (int k = 0; k < 3; ++k)
            m.vertices.push_back({window_to_clip(u(rng) * W, u(rng) * H, W, H, u(rng)), glm::vec3(u(rng), u(rng), u(rng))});
        out.push_back(m);
    }
    return out;
}

}  // namespace

TEST(HiddenSurfaceRemoval, SamePictureAsDrawingEverything) {
    const std::vector<RgbMesh> meshes = layers();
    for (int samples : {1, 4})
        for (DepthCase c : kDepthCases) {
            const SamplePicture two_pass = draw_rgb_meshes<true>(150, 100, samples, c, meshes);
            const SamplePicture plain = draw_rgb_meshes<false>(150, 100, samples, c, meshes);
            EXPECT_TRUE(two_pass.color == plain.color) << "color differs, samples " << samples << " func " << int(c.func);
            EXPECT_TRUE(two_pass.depth == plain.depth) << "depth differs, samples " << samples << " func " << int(c.func);
            EXPECT_LT(two_pass.shaded, plain.shaded);  // and it did save shading
        }
}

// Which runs take two passes: several draws whose bounds cover the tile 2.5 times over, or 8
// times with MSAA (whose second pass shades a pixel at a time).
TEST(HiddenSurfaceRemoval, RunsWorthTwoPasses) {
    struct Draw {
        double area;
        bool allows = true;
        bool allows_hidden_surface_removal() const { return allows; }
        uint32_t triangles_in_tile(int) const { return 1; }
        double covered_area(int) const { return area; }
    };
    const Rect tile{0, 0, 64, 64};
    const double full = 64.0 * 64.0;
    auto run = [&](std::vector<Draw>& draws, int samples) {
        std::vector<const Draw*> ptrs;
        for (const Draw& d : draws) ptrs.push_back(&d);
        return hidden_surface_run(std::span<const Draw* const>(ptrs), 0, 0, tile, samples);
    };
    std::vector<Draw> three = {{full}, {full}, {full}};  // overdraw 3
    EXPECT_TRUE(run(three, 1).worth_it);
    EXPECT_FALSE(run(three, 4).worth_it);
    EXPECT_EQ(run(three, 4).end, 3u);
    std::vector<Draw> eight(8, Draw{full});
    EXPECT_TRUE(run(eight, 4).worth_it);
    std::vector<Draw> one = {{10 * full}};  // one draw: nothing between draws to remove
    EXPECT_FALSE(run(one, 1).worth_it);
    std::vector<Draw> blended = {{full}, {full}, {full, false}, {full}};  // the run ends at a draw that does not allow it
    EXPECT_EQ(run(blended, 1).end, 2u);
    EXPECT_FALSE(run(blended, 1).worth_it);
}
