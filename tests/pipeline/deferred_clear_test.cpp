// The framebuffer's deferred clears (framebuffer.h): a tile nothing draws in keeps only its
// clear's values, and every way of reading the buffer sees them as if they had been written.
#include <gtest/gtest.h>

#include "softraster/context.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/worker_pool.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

// A small triangle in the first tile (pixels about 5..25 across and down) at depth z.
void draw_corner_triangle(Context& ctx, const Framebuffer& fb, glm::vec4 color, float z = 0.5f) {
    const std::vector<ClipVertexIn> v = {{window_to_clip(5, 5, fb.width(), fb.height(), z)},
                                         {window_to_clip(25, 5, fb.width(), fb.height(), z)},
                                         {window_to_clip(5, 25, fb.width(), fb.height(), z)}};
    ctx.state.cull = CullMode::None;
    draw(ctx, ConstantColorShader{color}, v, {0, 1, 2});
}

TEST(DeferredClear, TilesNothingDrawsInReadAsCleared) {
    WorkerPool pool(2);
    for (int samples : {1, 4}) {
        Framebuffer fb(200, 150, samples, ColorSpace::Srgb);
        Context ctx(fb, &pool);
        const glm::vec4 background(0.2f, 0.4f, 0.6f, 1.0f);
        const Rgba8 stored = quantize_rgba8(background, ColorSpace::Srgb);
        ctx.clear(background, 0.25f);
        draw_corner_triangle(ctx, fb, glm::vec4(1, 0, 0, 1), 0.1f);
        // The drawn tile is written; the others are not yet.
        EXPECT_EQ(fb.deferred(0), nullptr);
        for (int t = 1; t < fb.tiles().count(); ++t) ASSERT_NE(fb.deferred(t), nullptr) << t;
        // The resolve takes their pixels from the record, with or without threads.
        for (WorkerPool* p : {static_cast<WorkerPool*>(nullptr), &pool}) {
            Image img;
            resolve(fb, img, p);
            EXPECT_EQ(img.at(10, 8), (Rgba8{255, 0, 0, 255}));
            EXPECT_EQ(img.at(40, 40), stored);
            for (int y = 0; y < img.height; ++y)
                for (int x = 64; x < img.width; ++x) ASSERT_EQ(img.at(x, y), stored) << x << " " << y;
        }
        ASSERT_NE(fb.deferred(1), nullptr);
        // Reading the samples writes every deferred clear first.
        const float* depth = fb.depth_data();
        for (int t = 0; t < fb.tiles().count(); ++t) EXPECT_EQ(fb.deferred(t), nullptr);
        for (int y = 0; y < fb.height(); ++y)
            for (int x = 64; x < fb.width(); ++x)
                for (int s = 0; s < samples; ++s) {
                    ASSERT_EQ(depth[fb.sample_index(x, y, s)], 0.25f);
                    ASSERT_EQ(fb.color_data()[fb.sample_index(x, y, s)], stored);
                }
        EXPECT_FLOAT_EQ(depth[fb.sample_index(10, 8)], 0.1f);
    }
}

// A depth-only clear of a tile whose clear is deferred changes the recorded depth, which the
// next draw there tests against.
TEST(DeferredClear, ADepthClearChangesTheRecordedDepth) {
    Framebuffer fb(128, 64, 4);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 1, 1), 1.0f);
    ctx.clear_depth(0.5f);
    draw_corner_triangle(ctx, fb, glm::vec4(1, 0, 0, 1), 0.7f);  // behind 0.5: hidden
    EXPECT_EQ(fb.read_pixels().at(10, 8), (Rgba8{0, 0, 255, 255}));
    draw_corner_triangle(ctx, fb, glm::vec4(0, 1, 0, 1), 0.3f);  // in front
    EXPECT_EQ(fb.read_pixels().at(10, 8), (Rgba8{0, 255, 0, 255}));
    EXPECT_EQ(fb.depth_data()[fb.sample_index(100, 10)], 0.5f);
}

// Frame after frame: a clear defers again over a drawn tile, and a stencil buffer added
// after a deferred clear starts at 0, as it did before clears were deferred.
TEST(DeferredClear, LaterFramesAndALaterStencil) {
    Framebuffer fb(100, 70);
    Context ctx(fb);
    ctx.clear(glm::vec4(1, 1, 1, 1), 1.0f, 7);
    draw_corner_triangle(ctx, fb, glm::vec4(1, 0, 0, 1));
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.finish();
    EXPECT_NE(fb.deferred(0), nullptr);
    EXPECT_EQ(fb.read_pixels().at(10, 8), (Rgba8{0, 0, 0, 255}));
    fb.add_stencil();
    EXPECT_EQ(fb.deferred(0), nullptr);
    for (int y = 0; y < fb.height(); ++y)
        for (int x = 0; x < fb.width(); ++x) {
            ASSERT_EQ(fb.stencil_data()[fb.sample_index(x, y)], 0);
            ASSERT_EQ(fb.color_data()[fb.sample_index(x, y)], (Rgba8{0, 0, 0, 255}));
        }
}

}  // namespace
