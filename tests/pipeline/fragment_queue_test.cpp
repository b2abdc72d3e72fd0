// The fragment queue (fragment_queue.h) and the 32-bit coverage of small triangles
// (rasterization_small.h) must not change the picture: many tiny overlapping triangles,
// drawn by a pure shader (queued: depth now, shading later in groups of eight) and by the
// same shader marked impure (shaded triangle by triangle), give byte-identical color and
// depth, with and without MSAA, both facings, for several depth functions.
#include <gtest/gtest.h>

#include <random>

#include "softraster/pipeline/rasterization_small.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

struct RgbVaryings {
    float r, g, b;
};
struct RgbVertex {
    glm::vec4 clip;
    glm::vec3 color;
};

template <bool Pure>
struct RgbShader {
    using Vertex = RgbVertex;
    using Varyings = RgbVaryings;
    static constexpr bool kPure = Pure;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out = {in.color.r, in.color.g, in.color.b};
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord& f, glm::vec4& c) const {
        c = glm::vec4(v.r, v.g, f.front_facing ? v.b : 1.0f - v.b, 1.0f);
        return true;
    }
    void fragment_batch(const std::array<simd::f8, 3>& v, simd::f8, bool front_facing, std::array<simd::f8, 4>& c) const {
        c = {v[0], v[1], front_facing ? v[2] : 1.0f - v[2], simd::splat(1.0f)};
    }
};

template <bool Pure>
std::pair<std::vector<Rgba8>, std::vector<float>> render(int samples, DepthFunc func, float clear_depth, uint64_t& shaded) {
    constexpr int W = 203, H = 141;  // not a multiple of 8 or 64
    Framebuffer fb(W, H, samples);
    WorkerPool pool(2);
    Context ctx(fb, &pool);
    ctx.clear(glm::vec4(0, 0, 0, 1), clear_depth);
    ctx.state.cull = CullMode::None;
    ctx.state.depth_func = func;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<RgbVertex> v;
    std::vector<uint32_t> idx;
    for (int k = 0; k < 6000; ++k) {  // clustered, so that a group of eight often hits one pixel twice
        const float cx = 20 + u(rng) * (W - 10), cy = u(rng) * H, size = k % 7 == 0 ? 40.0f : 0.5f + 4 * u(rng), z = u(rng);
        for (int c = 0; c < 3; ++c) {
            idx.push_back(uint32_t(v.size()));
            v.push_back({window_to_clip(cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), W, H, z + 0.1f * u(rng), 1 + u(rng)),
                         glm::vec3(u(rng), u(rng), u(rng))});
        }
    }
    ctx.draw(Topology::Triangles, RgbShader<Pure>{}, std::span<const RgbVertex>(v), std::span<const uint32_t>(idx));
    ctx.execute();
    shaded = ctx.fragments_shaded();
    const size_t n = size_t(W) * H * size_t(samples);
    return {std::vector<Rgba8>(fb.color_data(), fb.color_data() + n), std::vector<float>(fb.depth_data(), fb.depth_data() + n)};
}

}  // namespace

TEST(FragmentQueue, SamePictureAsShadingEachTriangle) {
    struct Case {
        DepthFunc f;
        float clear;
    };
    for (int samples : {1, 4})
        for (Case c : {Case{DepthFunc::Less, 1.0f}, Case{DepthFunc::LessEqual, 1.0f}, Case{DepthFunc::Greater, 0.0f},
                       Case{DepthFunc::Always, 1.0f}}) {
            uint64_t shaded_queued = 0, shaded_plain = 0;
            const auto queued = render<true>(samples, c.f, c.clear, shaded_queued);
            const auto plain = render<false>(samples, c.f, c.clear, shaded_plain);
            EXPECT_TRUE(queued.first == plain.first) << "color differs, samples " << samples << " func " << int(c.f);
            EXPECT_TRUE(queued.second == plain.second) << "depth differs, samples " << samples << " func " << int(c.f);
            EXPECT_EQ(shaded_queued, shaded_plain);
            EXPECT_GT(shaded_queued, 10000u);
        }
}

// Coverage in 32-bit lanes equals the 64-bit per-pixel coverage of rasterization.h.
template <int Samples>
void expect_small_coverage_matches() {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    const Rect tile{64, 128, 128, 192};
    int tested = 0;
    for (int k = 0; k < 3000; ++k) {
        const float cx = 50 + 90 * u(rng), cy = 115 + 90 * u(rng), size = 1 + 63 * u(rng) * u(rng);
        std::array<ShadedVertex<1>, 3> p;
        for (auto& q : p) {
            ClipVertex<1> c{window_to_clip(cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), 256, 256), {}};
            ASSERT_TRUE(finish_vertex(c, Viewport{256, 256}, q));
        }
        if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) == 0) continue;
        TriangleSetup<1> t;
        if (!setup_triangle(p[0], p[1], p[2], FrontFace::CCW, tile, t) || !has_small_edges(t)) continue;
        std::vector<unsigned> expected(64 * 64, 0), got(64 * 64, 0);
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
            expected[size_t((px.y - tile.y0) * 64 + px.x - tile.x0)] = px.mask;
        });
        using G = GroupSamples<Samples>;
        rasterize_small<Samples>(t, [&](int y, int x, const std::array<simd::i8, G::kVectors>& covered) {
            for (int v = 0; v < G::kVectors; ++v)
                for (int l = 0; l < simd::kLanes; ++l)
                    if (covered[size_t(v)][l]) {
                        const int px = x + G::pixel(v)[l], s = Samples == 1 ? 0 : l % 4;
                        got[size_t((y - tile.y0) * 64 + px - tile.x0)] |= 1u << s;
                    }
        });
        ASSERT_EQ(expected, got) << "triangle " << k;
        ++tested;
    }
    EXPECT_GT(tested, 500);
}

TEST(SmallTriangleRasterization, SameCoverageAs64BitEdgesSingleSample) { expect_small_coverage_matches<1>(); }
TEST(SmallTriangleRasterization, SameCoverageAs64BitEdgesMsaa) { expect_small_coverage_matches<4>(); }
