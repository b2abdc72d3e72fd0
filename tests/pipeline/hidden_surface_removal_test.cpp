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

struct ColorVaryings {
    float r, g, b;
};
struct ColorVertex {
    glm::vec4 clip;
    glm::vec3 color;
};

template <bool Pure>
struct ColorShader {
    using Vertex = ColorVertex;
    using Varyings = ColorVaryings;
    static constexpr bool kPure = Pure;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out = {in.color.r, in.color.g, in.color.b};
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord&, glm::vec4& c) const {
        c = glm::vec4(v.r, v.g, v.b, 1.0f);
        return true;
    }
};

template <bool Pure>
std::pair<std::vector<Rgba8>, std::vector<float>> render(int samples, DepthFunc func, float clear_depth, uint64_t& shaded) {
    constexpr int W = 150, H = 100;
    Framebuffer fb(W, H, samples);
    WorkerPool pool(2);
    Context ctx(fb, &pool);
    ctx.clear(glm::vec4(0, 0, 0, 1), clear_depth);
    ctx.state.cull = CullMode::None;
    ctx.state.depth_func = func;
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<std::vector<ColorVertex>> layers;
    const std::vector<uint32_t> quad = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    for (int l = 0; l < 12; ++l) {
        std::vector<ColorVertex> v;
        const float z = float(l % 5) * 0.1f + 0.2f;  // repeated depths: ties
        const float x0 = u(rng) * W * 0.5f - 10, y0 = u(rng) * H * 0.5f - 10, x1 = x0 + 40 + u(rng) * W, y1 = y0 + 30 + u(rng) * H;
        for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y1)})
            v.push_back({window_to_clip(p.x, p.y, W, H, z + 0.05f * u(rng), 1.0f + u(rng)), glm::vec3(u(rng), u(rng), u(rng))});
        for (int k = 0; k < 3; ++k)  // and a slanted triangle that cuts through the others
            v.push_back({window_to_clip(u(rng) * W, u(rng) * H, W, H, u(rng)), glm::vec3(u(rng), u(rng), u(rng))});
        layers.push_back(v);
    }
    for (const auto& v : layers) ctx.draw(Topology::Triangles, ColorShader<Pure>{}, std::span<const ColorVertex>(v), std::span<const uint32_t>(quad));
    ctx.execute();
    shaded = ctx.fragments_shaded();
    const size_t n = size_t(W) * H * size_t(samples);
    return {std::vector<Rgba8>(fb.color_data(), fb.color_data() + n), std::vector<float>(fb.depth_data(), fb.depth_data() + n)};
}

}  // namespace

TEST(HiddenSurfaceRemoval, SamePictureAsDrawingEverything) {
    struct Case {
        DepthFunc f;
        float clear;
    };
    for (int samples : {1, 4})
        for (Case c : {Case{DepthFunc::Less, 1.0f}, Case{DepthFunc::LessEqual, 1.0f}, Case{DepthFunc::Greater, 0.0f},
                       Case{DepthFunc::Always, 1.0f}}) {
            uint64_t shaded_two_pass = 0, shaded_plain = 0;
            const auto two_pass = render<true>(samples, c.f, c.clear, shaded_two_pass);
            const auto plain = render<false>(samples, c.f, c.clear, shaded_plain);
            EXPECT_TRUE(two_pass.first == plain.first) << "color differs, samples " << samples << " func " << int(c.f);
            EXPECT_TRUE(two_pass.second == plain.second) << "depth differs, samples " << samples << " func " << int(c.f);
            EXPECT_LT(shaded_two_pass, shaded_plain);  // and it did save shading
        }
}
