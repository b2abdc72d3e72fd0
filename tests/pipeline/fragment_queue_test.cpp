// The fragment queue (fragment_queue.h) and the 32-bit coverage of small triangles
// (rasterization_small.h) must not change the picture: many tiny overlapping triangles,
// drawn by a pure shader (queued: depth now, shading later in groups of eight) and by the
// same shader marked impure (shaded triangle by triangle), give byte-identical color and
// depth, with and without MSAA, both facings, for several depth functions.
#include <gtest/gtest.h>

#include <atomic>
#include <random>

#include "softraster/pipeline/rasterization_small.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 203, H = 141;  // not a multiple of 8 or 64

// One draw of 6000 triangles, mostly a few pixels big and clustered (so that a group of
// eight queued fragments often hits one pixel twice), some bigger ones, both facings.
RgbMesh tiny_triangles() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    RgbMesh m;
    for (int k = 0; k < 6000; ++k) {
        const float cx = 20 + u(rng) * (W - 10), cy = u(rng) * H, size = k % 7 == 0 ? 40.0f : 0.5f + 4 * u(rng), z = u(rng);
        for (int c = 0; c < 3; ++c) {
            m.indices.push_back(uint32_t(m.vertices.size()));
            m.vertices.push_back({window_to_clip(cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), W, H, z + 0.1f * u(rng), 1 + u(rng)),
                                  glm::vec3(u(rng), u(rng), u(rng))});
        }
    }
    return m;
}

}  // namespace

TEST(FragmentQueue, SamePictureAsShadingEachTriangle) {
    // The queue is in the AVX2 copy only (tile_back_end.h): there the pure shader's picture
    // is the queue's. The reference is the impure shader's on the generic path, shaded
    // triangle by triangle, which never queues; the pure shader on the generic path must
    // give it too.
    if (!simd::wide_path_runs()) GTEST_SKIP() << "no AVX2 path here (this CPU, or a SOFTRASTER_GENERIC_ONLY build): the fragment queue never runs";
    const std::vector<RgbMesh> meshes = {tiny_triangles()};
    for (int samples : {1, 4})
        for (DepthCase c : kDepthCases) {
            std::atomic<uint64_t> queued_calls{0}, wide_calls{0}, plain_calls{0}, generic_calls{0};
            simd::use_generic_path(false);
            const SamplePicture queued = draw_rgb_meshes<true>(W, H, samples, c, meshes, &queued_calls);
            const SamplePicture wide = draw_rgb_meshes<false>(W, H, samples, c, meshes, &wide_calls);
            simd::use_generic_path(true);
            const SamplePicture plain = draw_rgb_meshes<false>(W, H, samples, c, meshes, &plain_calls);
            const SamplePicture generic = draw_rgb_meshes<true>(W, H, samples, c, meshes, &generic_calls);
            simd::use_generic_path(false);
            // The queue ran: its shader calls carry eight fragments nearly every time, where
            // shading triangle by triangle leaves most lanes of these tiny triangles empty
            // (or, with MSAA, shades them one at a time).
            ASSERT_GT(queued_calls.load(), 0u);
            EXPECT_GT(double(queued.shaded) / double(queued_calls.load()), 6.5) << "samples " << samples;
            if (samples == 1) {
                EXPECT_LT(double(wide.shaded) / double(wide_calls.load()), 6.5);
            } else {
                EXPECT_EQ(wide_calls.load(), 0u);
            }
            for (const SamplePicture* other : {&wide, &plain, &generic}) {
                const char* which = other == &wide ? "impure, AVX2" : other == &plain ? "impure, generic" : "pure, generic";
                EXPECT_TRUE(queued.color == other->color) << "color differs from the " << which << " one, samples " << samples << " func " << int(c.func);
                EXPECT_TRUE(queued.depth == other->depth) << "depth differs from the " << which << " one, samples " << samples << " func " << int(c.func);
                EXPECT_EQ(queued.shaded, other->shaded);
            }
            EXPECT_GT(queued.shaded, 10000u);
        }
}

// The per-pixel sample masks a group rasterizer (rasterization_small.h) reports, as
// rasterize_triangle reports them.
template <int Samples, class Rasterize>
std::vector<unsigned> group_coverage(const TriangleSetup<1>& t, const Rect& tile, Rasterize&& rasterize) {
    std::vector<unsigned> got(64 * 64, 0);
    using G = GroupSamples<Samples>;
    rasterize(t, [&](int y, int x, const std::array<simd::i8, G::kVectors>& covered) {
        for (int v = 0; v < G::kVectors; ++v)
            for (int l = 0; l < simd::kLanes; ++l)
                if (covered[size_t(v)][l]) {
                    const int px = x + G::pixel(v)[l], s = Samples == 1 ? 0 : l % 4;
                    got[size_t((y - tile.y0) * 64 + px - tile.x0)] |= 1u << s;
                }
    });
    return got;
}

// Coverage in 32-bit lanes (small triangles), and from each row's spans (any triangle),
// equals the 64-bit per-pixel coverage of rasterization.h.
template <int Samples>
void expect_group_coverage_matches() {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    const Rect tile{64, 128, 128, 192};
    int small = 0, big = 0, blocks = 0;
    for (int k = 0; k < 4000; ++k) {
        const bool huge = k % 4 == 3;  // (edges far past the tile, and past kSmallEdge)
        const float cx = 50 + 90 * u(rng), cy = 115 + 90 * u(rng), size = huge ? 64 + 2000 * u(rng) : 1 + 63 * u(rng) * u(rng);
        std::array<ShadedVertex<1>, 3> p;
        ASSERT_TRUE(random_triangle(rng, cx, cy, size, size, p));
        if (signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y) == 0) continue;
        TriangleSetup<1> t;
        if (!setup_triangle<Samples>(p[0], p[1], p[2], FrontFace::CCW, tile, t)) continue;
        std::vector<unsigned> expected(64 * 64, 0);
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
            expected[size_t((px.y - tile.y0) * 64 + px.x - tile.x0)] = px.mask;
        });
        auto spans = [](const TriangleEdges& e, auto&& on_group) { rasterize_span_groups<Samples>(e, on_group); };
        ASSERT_EQ(expected, group_coverage<Samples>(t, tile, spans)) << "spans, triangle " << k;
        ++big;
        if (!has_small_edges(t)) continue;
        auto lanes = [](const TriangleEdges& e, auto&& on_group) { rasterize_small<Samples>(e, on_group); };
        ASSERT_EQ(expected, group_coverage<Samples>(t, tile, lanes)) << "32-bit lanes, triangle " << k;
        ++small;
        const int bw = t.bounds.x1 - t.bounds.x0;
        if (Samples != 1 || bw > kBlockColumns) continue;
        // Blocks of 4x2, from the bounds' first pixel or left of it (as far as the block
        // still reaches the bounds' last column) and one row above (as the queue starts them
        // nearer a tile's far edges).
        const int dx = k % (kBlockColumns - bw + 1), dy = (k / 4) % 2;
        std::vector<unsigned> got(64 * 64, 0);
        rasterize_blocks(t, t.bounds.x0 - dx, t.bounds.y0 - dy, [&](int x, int y, simd::i8 covered) {
            for (int l = 0; l < simd::kLanes; ++l)
                if (covered[l]) got[size_t((y + l / 4 - tile.y0) * 64 + x + l % 4 - tile.x0)] |= 1u;
        });
        ASSERT_EQ(expected, got) << "blocks, triangle " << k << " from (" << -dx << ", " << -dy << ")";
        ++blocks;
    }
    EXPECT_GT(small, 500);
    EXPECT_GT(big - small, 300);
    if (Samples == 1) {
        EXPECT_GT(blocks, 100);
    }
}

TEST(GroupRasterization, SameCoverageAs64BitEdgesSingleSample) { expect_group_coverage_matches<1>(); }
TEST(GroupRasterization, SameCoverageAs64BitEdgesMsaa) { expect_group_coverage_matches<4>(); }
