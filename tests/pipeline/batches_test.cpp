// The context's batches (Context::batching): the recorded commands run through the whole
// pipeline a batch at a time, and the picture is the same however they are split.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "softraster/thread_vote.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 150, H = 100;

// Forty draws over three tiles: overlapping quads at repeated depths (ties), which make
// runs worth hidden-surface removal's two passes, and between them draws of a few tiny
// triangles (the fragment queue's).
std::vector<RgbMesh> overlapping_draws() {
    std::mt19937 rng(43);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<RgbMesh> out;
    for (int d = 0; d < 40; ++d) {
        RgbMesh m;
        auto vertex = [&](float x, float y, float z) { m.vertices.push_back({window_to_clip(x, y, W, H, z, 1.0f + u(rng)), glm::vec3(u(rng), u(rng), u(rng))}); };
        if (d % 3 == 2) {
            for (int t = 0; t < 20; ++t) {
                const float x = u(rng) * W, y = u(rng) * H, z = u(rng);
                for (int k = 0; k < 3; ++k) vertex(x + 4 * u(rng), y + 4 * u(rng), z);
                for (uint32_t k = 0; k < 3; ++k) m.indices.push_back(uint32_t(3 * t) + k);
            }
        } else {
            const float z = float(d % 5) * 0.1f + 0.2f;
            const float x0 = u(rng) * W * 0.5f - 10, y0 = u(rng) * H * 0.5f - 10, x1 = x0 + 40 + u(rng) * W, y1 = y0 + 30 + u(rng) * H;
            for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y1)}) vertex(p.x, p.y, z + 0.05f * u(rng));
            m.indices = {0, 1, 2, 0, 2, 3};
        }
        out.push_back(m);
    }
    return out;
}

}  // namespace

// One batch, a batch per command, and batches of five give the same samples through every
// back end: the pure shader's (two passes, the fragment queue), the plain one and the general
// one, with and without MSAA, for every depth function; and but for the two passes' savings,
// they shade the same fragments.
TEST(Batches, SamePictureInAnySplit) {
    const std::vector<RgbMesh> draws = overlapping_draws();
    const size_t commands = draws.size() + 1;  // (and the clear)
    const Context::Batching each{0, 1}, fives{0, 5};
    for (int samples : {1, 4})
        for (DepthCase c : kDepthCases)
            for (int path = 0; path < 3; ++path) {
                auto picture = [&](Context::Batching b) {
                    if (path == 0) return draw_rgb_meshes<true>(W, H, samples, c, draws, nullptr, false, b);
                    return draw_rgb_meshes<false>(W, H, samples, c, draws, nullptr, /*stencil_always=*/path == 2, b);
                };
                const SamplePicture whole = picture({});
                const SamplePicture split = picture(each), in_fives = picture(fives);
                const std::string where = "samples " + std::to_string(samples) + " func " + std::to_string(int(c.func)) + " path " + std::to_string(path);
                ASSERT_EQ(whole.batches, 1u) << where;
                ASSERT_EQ(split.batches, commands) << where;
                ASSERT_EQ(in_fives.batches, (commands + 4) / 5) << where;
                for (const SamplePicture* p : {&split, &in_fives}) {
                    EXPECT_TRUE(p->color == whole.color) << "color differs, " << where;
                    EXPECT_TRUE(p->depth == whole.depth) << "depth differs, " << where;
                    // (Hidden-surface removal's runs end with their batch: split, it saves less.)
                    if (path == 0) EXPECT_GE(p->shaded, whole.shaded) << where;
                    else EXPECT_EQ(p->shaded, whole.shaded) << where;
                }
            }
}

// A batch closes at the first command that brings it to `draws` commands and `bytes` of
// post-transform vertices; by default 256 and 2 MB.
TEST(Batches, CloseAtTheirDrawsAndBytes) {
    Framebuffer fb(64, 64);
    Context ctx(fb);
    // 600 draws of 1,000 vertices each (all behind the eye: nothing to rasterize).
    const std::vector<ClipVertexIn> vertices(1000, ClipVertexIn{glm::vec4(0, 0, -2, 1)});
    const std::vector<uint32_t> indices = {0, 1, 2};
    for (int d = 0; d < 600; ++d) ctx.draw(Topology::Triangles, ConstantColorShader{}, std::span(vertices), std::span(indices));
    const size_t per_draw = vertices.size() * sizeof(ShadedVertex<1>);
    auto expected = [&] {
        const size_t per_batch = std::max(ctx.batching.draws, (ctx.batching.bytes + per_draw - 1) / per_draw);
        return (600 + per_batch - 1) / per_batch;
    };
    ASSERT_EQ(ctx.batching.draws, 256u);
    ASSERT_EQ(ctx.batching.bytes, size_t(2) << 20);
    ASSERT_LT(ctx.batching.bytes / per_draw, 256u);  // the draws decide: 256, 256 and 88
    ctx.execute();
    EXPECT_EQ(ctx.batches(), 3u);
    ctx.batching.draws = 10;  // the bytes decide
    ctx.execute();
    EXPECT_EQ(ctx.batches(), expected());
    EXPECT_GT(ctx.batches(), 3u);
    ctx.batching.bytes = 0;  // the draws alone
    ctx.execute();
    EXPECT_EQ(ctx.batches(), 60u);
}

// A small draw's vote (Context::list_commands_by_tile): the thread of most of its tiles,
// ties to the lowest, each draw counted afresh.
TEST(Batches, AVoteGoesToTheThreadOfMostTilesTiesToTheLowest) {
    ThreadVote vote(3);
    vote.start();
    EXPECT_EQ(vote.winner(), 0u);  // no tiles
    for (unsigned t : {2u, 1u, 2u}) vote.add(t);
    EXPECT_EQ(vote.winner(), 2u);
    vote.start();  // the last draw's two tiles of thread 2 no longer count
    for (unsigned t : {2u, 1u, 1u}) vote.add(t);
    EXPECT_EQ(vote.winner(), 1u);
    vote.start();
    for (unsigned t : {2u, 1u}) vote.add(t);  // a tie, whichever came first
    EXPECT_EQ(vote.winner(), 1u);
    vote.start();
    for (unsigned t : {1u, 2u, 0u, 2u, 1u, 0u}) vote.add(t);
    EXPECT_EQ(vote.winner(), 0u);
}

// With more than one thread, each batch's tiles go to the threads in bands and a small
// draw's front end, from the second execution on, to the thread of its band
// (Context::split_tiles, and the votes below). The picture is the same on any number of threads, execution after
// execution: scattered small draws, a small draw over more tiles than a footprint holds
// (64), a draw too big to be small (two chunks of vertices), and a clear, in batches of
// several sizes, and batches of draws along a strip (cut into bands column by column).
TEST(Batches, SamePictureOnAnyThreadsExecutionAfterExecution) {
    constexpr int kW = 700, kH = 450;  // 11 x 8 tiles
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<RgbMesh> meshes;
    auto quad = [&](float x0, float y0, float x1, float y1, float z) {
        RgbMesh m;
        const glm::vec3 color(u(rng), u(rng), u(rng));
        for (glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y1)})
            m.vertices.push_back({window_to_clip(p.x, p.y, kW, kH, z), color});
        m.indices = {0, 1, 2, 0, 2, 3};
        return m;
    };
    meshes.push_back(quad(-20, -20, kW + 20, kH + 20, 0.9f));  // every tile: its footprint asks the command
    for (int d = 0; d < 60; ++d) {  // a strip one or two tiles tall: its batches' bands are cut column by column
        const float x = u(rng) * kW;
        meshes.push_back(quad(x, 200 + u(rng) * 20, x + 10 + u(rng) * 40, 230 + u(rng) * 20, u(rng) * 0.8f));
    }
    for (int d = 0; d < 300; ++d) {
        const float x = u(rng) * kW, y = u(rng) * kH, s = 4 + u(rng) * 120;
        meshes.push_back(quad(x, y, x + s, y + s * (0.5f + u(rng)), u(rng) * 0.8f));
    }
    RgbMesh big;  // 17,400 vertices: more than a chunk of vertex processing
    for (int k = 0; k < 5800; ++k) {
        const float x = u(rng) * kW, y = u(rng) * kH, z = u(rng) * 0.8f;
        for (int c = 0; c < 3; ++c) big.vertices.push_back({window_to_clip(x + 6 * u(rng), y + 6 * u(rng), kW, kH, z), glm::vec3(u(rng), 0.5f, 0.5f)});
        for (uint32_t c = 0; c < 3; ++c) big.indices.push_back(uint32_t(3 * k) + c);
    }
    ASSERT_GT(big.vertices.size(), kVertexChunk);
    meshes.insert(meshes.begin() + 150, big);

    auto picture = [&](unsigned threads, Context::Batching batching, int executions) {
        Framebuffer fb(kW, kH);
        std::optional<WorkerPool> pool;
        if (threads > 0) pool.emplace(threads);
        Context ctx(fb, pool ? &*pool : nullptr);
        ctx.batching = batching;
        ctx.clear(glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
        for (const RgbMesh& m : meshes)
            ctx.draw(Topology::Triangles, RgbShader<true>{}, std::span<const RgbVertex>(m.vertices), std::span<const uint32_t>(m.indices));
        std::vector<std::vector<Rgba8>> colors;
        for (int e = 0; e < executions; ++e) {
            ctx.execute();
            colors.emplace_back(fb.color_data(), fb.color_data() + size_t(kW) * kH);
        }
        return colors;
    };
    const std::vector<Rgba8> expected = picture(0, {}, 1)[0];
    for (Context::Batching batching : {Context::Batching{}, Context::Batching{0, 40}, Context::Batching{0, 7}})
        for (unsigned threads : {2u, 3u}) {
            const auto colors = picture(threads, batching, 3);
            for (size_t e = 0; e < colors.size(); ++e)
                EXPECT_TRUE(colors[e] == expected) << threads << " threads, batches of " << batching.draws << " draws, execution " << e + 1;
        }
}
