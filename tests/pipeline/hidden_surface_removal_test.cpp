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
