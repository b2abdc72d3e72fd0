// The tile back end: one draw's triangles in one tile, each through the per-pixel stages:
//   triangle setup (triangle_setup.h) -> rasterization (rasterization.h, and
//   rasterization_small.h for small triangles) -> early depth test (depth_stencil.h) ->
//   interpolation (interpolation.h) -> fragment shading (fragment_shading.h, through the
//   fragment queue of fragment_queue.h for small triangles) -> output merge (output_merge.h).
// The tile's thread runs the tile's draws in draw order (Context::execute); runs of opaque
// draws with heavy overdraw take two passes instead (hidden_surface_removal.h).
//
// It is compiled per varying layout (shader_layout.h) and sample count, not per shader or
// blend mode: the shader's fragment code is called out of line, a batch of groups at a
// time, and whether the draw blends is chosen per batch (shade_and_merge) or per triangle.
#pragma once
#include <array>
#include <cstdint>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binned_triangles.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/fragment_queue.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/rasterization_small.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/render_state.h"

namespace softraster {

template <class L, int Samples>
struct TileBackEnd {
    static constexpr int N = L::N;
    static constexpr uint64_t Flat = L::kFlat;
    // Blended draws of shaders that read varyings alone shade a triangle whose varyings are
    // constant once (draw_groups); setup looks for those only in them (setup_planes).
    bool find_constant() const { return shader.code->varyings_only && blend.blends(); }
    // Single-sampled opaque draws may test stencil too: general_back_end.h sends those that
    // do here when nothing after the shader can drop a fragment. They run the fragment queue
    // or EightPixelGroups, with the stencil test where depth is tested: a choice made per
    // draw, not another copy of the back end per layout.
    static constexpr bool kMayStencil = Samples == 1;
    bool stencil() const { return kMayStencil && tests.stencil; }

    // By value, not by reference: the tile loops read them after every framebuffer store,
    // which may alias anything, so each reference would cost another load there.
    LayoutShader<L> shader;
    RenderState state;
    DepthStencilTest tests;  // the stencil test off but where the general back end turns it on
    BlendSettings blend;
    BinnedTriangles<N> triangles;
    Framebuffer& fb;

    // How the draw's triangles in a tile are rasterized and shaded:
    // - FragmentQueue: small triangles leave a group of eight pixels mostly empty, so
    //   their fragments are depth-tested at once and queued, then shaded eight at a time
    //   across triangles (fragment_queue.h). Needs a batch shader that never discards, an
    //   opaque draw (colors written later must not depend on what they overwrite) and
    //   color writes on. Big single-sampled triangles fill their groups anyway: they go
    //   straight through EightPixelGroups, the queue flushed first.
    // - EightPixelGroups: single-sampled, with a batch shader: rows in groups of eight
    //   pixels, tested, shaded and merged as vectors. Without wide (AVX2) lanes only
    //   triangles at least 16 pixels wide, where the lanes are mostly full.
    // - PixelByPixel: everything else (blended MSAA draws, shaders without a batch version
    //   or that may discard, narrow triangles on the generic path): one fragment at a time.
    //   The queue is in the AVX2 copy only. In the generic one, where eight lanes are two
    //   halves and the queue's lane shuffles are slow, the other two ways, with the same
    //   pixels, were faster (docs/performance.md: the fragment queue, and "Build time").
    enum class Strategy { FragmentQueue, EightPixelGroups, PixelByPixel };
    static constexpr bool kQueueable = L::kBatch && L::kPure;
    Strategy strategy() const {
        if (kQueueable && !blend.blends() && state.color_write && blend.color_mask) return Strategy::FragmentQueue;
        return Samples == 1 && L::kBatch ? Strategy::EightPixelGroups : Strategy::PixelByPixel;
    }

    // Draws the draw's triangles in tile (tx, ty), whose pixels are `rect`; returns the
    // fragments shaded. WideLanes: compiled for AVX2, where eight lanes are one register.
    template <bool WideLanes>
    uint64_t draw(int tx, int ty, const Rect& rect) const {
        const FragmentCalls<N>& calls = shader.code->path(WideLanes);
        uint64_t shaded = 0;
        // The groups waiting for their colors: one list per thread, off the stack (a few
        // kilobytes that would otherwise sit among the tile loop's spilled registers).
        static thread_local PendingGroups<N> pending[2];
        if constexpr (kQueueable && WideLanes) {
            if (strategy() == Strategy::FragmentQueue) {
                static thread_local FragmentQueue<N, Samples> queue;
                queue.start(calls.groups, shader.self, fb);
                // (Opaque: no constant varyings sought, see find_constant.)
                for_each_triangle_setup<Samples, /*Planes=*/false, Flat>(triangles, state, tx, ty, rect, [&](TriangleSetup<N>& setup, uint32_t) {
                    if constexpr (Samples == 1) {  // (else draw_groups would be compiled, never to run)
                        if (is_large(setup.bounds)) {
                            queue.flush();
                            setup_planes<Flat>(setup);
                            shaded += draw_groups<WideLanes>(calls, setup, pending);
                            return;
                        }
                    }
                    shaded += queue_triangle(setup, rect, queue);  // makes the planes if needed
                });
                queue.flush();
                return shaded;
            }
        }
        for_each_triangle_setup<Samples, true, Flat, /*Constant=*/true>(triangles, state, tx, ty, rect, [&](const TriangleSetup<N>& setup, uint32_t) {
            if constexpr (Samples == 1 && L::kBatch) {
                if (WideLanes || stencil() || setup.bounds.x1 - setup.bounds.x0 >= 16) {  // EightPixelGroups
                    shaded += draw_groups<WideLanes>(calls, setup, pending);
                    return;
                }
            }
            shaded += draw_pixels(calls, setup);
        }, find_constant());
        return shaded;
    }

    // A triangle at least this big in the tile fills its groups of eight without the queue.
    static bool is_large(const Rect& r) { return (r.x1 - r.x0) >= 32 && (r.y1 - r.y0) >= 16; }

    // PixelByPixel: each covered pixel's samples, depth-tested, shaded at the pixel center
    // and merged.
    uint64_t draw_pixels(const FragmentCalls<N>& calls, const TriangleSetup<N>& t) const {
        uint64_t shaded = 0;
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
            const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // the pixel center
            shade_fragment<Samples>(calls, shader.self, tests.depth, blend, fb, px.x, px.y, px.mask, px.z.data(),
                                             interpolate_depth(t, i, j), t.front_facing,
                                             [&] { return interpolate_varyings<L, true>(t, i, j); }, shaded);
        });
        return shaded;
    }

    // A row's depth and stencil values (found once per row, not per group); no stencil row
    // where the draw does not test stencil.
    struct DepthRow {
        float* depth;
        uint8_t* stencil;
    };
    DepthRow depth_row(int y) const {
        return {fb.depth_plane() + fb.sample_index(0, y), stencil() ? fb.stencil_plane() + fb.sample_index(0, y) : nullptr};
    }
    // The early depth (and stencil) test of group [x, x + 8) of a row of `width` at depths z.
    simd::i8 test_group(const DepthRow& row, int x, int width, simd::f8 z, simd::i8 covered, bool front_facing) const {
        if (kMayStencil && row.stencil) return tests.test_group(row.depth, row.stencil, x, width, z, covered, front_facing);
        return tests.depth.test_group(row.depth, x, width, z, covered);
    }

    // EightPixelGroups: each row's span in groups of eight; depth, 1/w and the varyings
    // from their planes for eight pixels at once, shaded a batch of groups at a time
    // (fragment_shading.h). pending[0] holds single groups, pending[1] quad-row pairs.
    // Out of line in each CPU path's copy (simd.h), like draw_rows below: the tile loop
    // calls it from two places, and each would otherwise compile it again.
    template <bool WideLanes>
    uint64_t draw_groups(const FragmentCalls<N>& calls, const TriangleSetup<N>& t, PendingGroups<N> (&pending)[2]) const
        requires(L::kBatch) {
        if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) return draw_groups_wide(calls, t, pending);
        else return draw_groups_generic(calls, t, pending);
    }
    [[gnu::noinline]] SOFTRASTER_AVX2_TARGET uint64_t draw_groups_wide(const FragmentCalls<N>& calls, const TriangleSetup<N>& t,
                                                                       PendingGroups<N> (&pending)[2]) const requires(L::kBatch) {
        return triangle_groups<true>(calls, t, pending);
    }
    [[gnu::noinline]] uint64_t draw_groups_generic(const FragmentCalls<N>& calls, const TriangleSetup<N>& t, PendingGroups<N> (&pending)[2]) const
        requires(L::kBatch) {
        return triangle_groups<false>(calls, t, pending);
    }
    template <bool WideLanes>
    uint64_t triangle_groups(const FragmentCalls<N>& calls, const TriangleSetup<N>& t, PendingGroups<N> (&pending)[2]) const
        requires(L::kBatch) {
        using namespace simd;
        uint64_t shaded = 0;
        PendingGroups<N>& groups = pending[0];
        PendingGroups<N>& pairs = pending[1];
        groups.start(t.front_facing);
        pairs.start(t.front_facing);
        // Constant varyings and a shader that reads nothing else: one color for the whole
        // triangle, shaded here once.
        std::array<f8, 4> constant_rgba{};
        const std::array<f8, 4>* constant = nullptr;
        if (t.constant_varyings) {  // (found only where find_constant)
            groups.add(0, 0, splat_i(0), splat(0.0f)) = interpolate_varyings<L, true>(t, splat(0.0f), splat(0.0f));
            calls.groups(shader.self, groups.batch);
            constant_rgba = groups.batch.rgba[0];
            constant = &constant_rgba;
            groups.batch.count = 0;
        }
        const Rows rows{calls, t, pending, constant};
        // A shader that shades two rows of quads at once (L::kQuadRows) gets the groups of a
        // quads' first row (y even) and of the row below together, the first row's span held
        // until the second's comes. Each pixel's test, color and merge are its own, so the
        // order between the rows changes nothing.
        bool pair_rows = false;
        if constexpr (L::kQuadRows) pair_rows = blend.mode != BlendMode::Custom && !constant && blend.color_mask && !stencil();
        Span held{-1, 0, 0};  // a quads' first row, waiting for the second
        rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
            const Span span{y, x_begin, x_end};
            if constexpr (L::kQuadRows) {
                if (pair_rows) {
                    if (held.y >= 0 && held.y == y - 1) {
                        shaded += draw_rows<WideLanes>(rows, held, span);
                        held.y = -1;
                        return;
                    }
                    if (held.y >= 0) shaded += draw_rows<WideLanes>(rows, held, {}), held.y = -1;  // (its second row has no pixels)
                    if ((y & 1) == 0) {
                        held = span;
                        return;
                    }
                }
            }
            // (Inline here, where most rows go: a call per row costs a few percent of a
            // frame of big triangles whose color is constant.)
            shaded += row_groups<WideLanes>(rows, span);
        });
        if constexpr (L::kQuadRows) {
            if (held.y >= 0) shaded += draw_rows<WideLanes>(rows, held, {});
            shade_and_merge<WideLanes>(calls.quad_rows, shader.self, blend, fb, pairs);
        }
        shade_and_merge<WideLanes>(calls.groups, shader.self, blend, fb, groups);
        return shaded;
    }

    // A row's span of pixels [begin, end); y < 0 for none.
    struct Span {
        int y = -1, begin = 0, end = 0;
    };
    // What draw_rows needs of draw_groups.
    struct Rows {
        const FragmentCalls<N>& calls;
        const TriangleSetup<N>& t;
        PendingGroups<N> (&pending)[2];
        const std::array<simd::f8, 4>* constant;
    };
    // The rows of the quad-row pairing, out of line in each CPU path's copy (simd.h):
    // draw_groups calls them from several places, and each would otherwise be compiled at each.
    template <bool WideLanes>
    uint64_t draw_rows(const Rows& r, const Span& first, const Span& second) const {
        if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) return second.y < 0 ? draw_row_wide(r, first) : draw_quad_rows_wide(r, first, second);
        else return second.y < 0 ? draw_row_generic(r, first) : draw_quad_rows_generic(r, first, second);
    }
    [[gnu::noinline]] SOFTRASTER_AVX2_TARGET uint64_t draw_row_wide(const Rows& r, const Span& span) const { return row_groups<true>(r, span); }
    [[gnu::noinline]] uint64_t draw_row_generic(const Rows& r, const Span& span) const { return row_groups<false>(r, span); }
    [[gnu::noinline]] SOFTRASTER_AVX2_TARGET uint64_t draw_quad_rows_wide(const Rows& r, const Span& first, const Span& second) const {
        return quad_row_groups<true>(r, first, second);
    }
    [[gnu::noinline]] uint64_t draw_quad_rows_generic(const Rows& r, const Span& first, const Span& second) const {
        return quad_row_groups<false>(r, first, second);
    }

    // The groups of a row's span, tested and queued for shading.
    template <bool WideLanes>
    uint64_t row_groups(const Rows& r, const Span& span) const {
        using namespace simd;
        const TriangleSetup<N>& t = r.t;
        PendingGroups<N>& groups = r.pending[0];
        uint64_t shaded = 0;
        const f8 j = splat(float(span.y - t.origin_y));
        const int width = fb.width();
        // One color for the whole triangle (r.constant): nothing to shade, so each group is
        // merged at once, a Custom blend's for the row together. (Copies in locals: the
        // framebuffer's stores could alias anything a pointer or reference reaches.)
        Rgba8* const color_row = fb.color_plane() + fb.sample_index(0, span.y);
        const DepthRow row = depth_row(span.y);
        const bool constant = r.constant != nullptr, custom_blend = blend.mode == BlendMode::Custom;
        const std::array<f8, 4> constant_rgba = constant ? *r.constant : std::array<f8, 4>{};
        RowGroups custom;
        i8 constant_packed{};
        SourceUnorm8 constant_source{};  // (quantized once for the row)
        if (constant && custom_blend) quantize_pack_rgba8(constant_rgba, constant_packed);
        else if (constant) constant_source = quantize_source</*Blended=*/true>(blend, constant_rgba);
        for_each_group(span.begin, span.end, [&](int x, i8 covered) {
            const f8 i = to_float(kLaneIndex) + float(x - t.origin_x);
            const f8 z = interpolate_depth(t, i, j);
            const i8 pass = test_group(row, x, width, z, covered, t.front_facing);
            if (!any(pass) || !blend.color_mask) return;  // (no color mask: a stencil or depth pass only)
            shaded += unsigned(__builtin_popcount(bits(pass)));
            if (constant) {
                if (custom_blend) custom.add(x, pass, constant_packed);
                else blend_group</*Blended=*/true>(blend, color_row, x, width, pass, constant_source);  // (only blended draws look)
                return;
            }
            groups.add(span.y, x, pass, z) = interpolate_varyings<L, true>(t, i, j);
            if (groups.full()) shade_and_merge<WideLanes>(r.calls.groups, shader.self, blend, fb, groups);
        });
        if (custom.count > 0) blend_row<WideLanes>(blend, color_row, width, custom);
        return shaded;
    }

    // The groups of a quads' first row and the row below it: where both rows of a group
    // have pixels that pass the test, a pair for the shader's quad-row call; else each
    // row's group on its own.
    template <bool WideLanes>
    uint64_t quad_row_groups(const Rows& r, const Span& first, const Span& second) const {
        using namespace simd;
        uint64_t shaded = 0;
        if constexpr (L::kQuadRows) {
            const TriangleSetup<N>& t = r.t;
            PendingGroups<N>& groups = r.pending[0];
            PendingGroups<N>& pairs = r.pending[1];
            const f8 j0 = splat(float(first.y - t.origin_y)), j1 = splat(float(second.y - t.origin_y));
            const int width = fb.width();
            const DepthRow rows[2] = {depth_row(first.y), depth_row(second.y)};
            for_each_group(std::min(first.begin, second.begin), std::max(first.end, second.end), [&](int x, i8) {
                const i8 px = kLaneIndex + x;
                const i8 covered[2] = {(px >= first.begin) & (px < first.end), (px >= second.begin) & (px < second.end)};
                const f8 i = to_float(kLaneIndex) + float(x - t.origin_x);
                const f8 z[2] = {interpolate_depth(t, i, j0), interpolate_depth(t, i, j1)};
                i8 pass[2];
                for (int k = 0; k < 2; ++k) pass[k] = any(covered[k]) ? test_group(rows[k], x, width, z[k], covered[k], t.front_facing) : splat_i(0);
                shaded += unsigned(__builtin_popcount(bits(pass[0]))) + unsigned(__builtin_popcount(bits(pass[1])));
                if (any(pass[0]) && any(pass[1])) {
                    std::array<f8, N>& top = pairs.add(first.y, x, pass[0], z[0]);
                    interpolate_quad_row_pair<L>(t, i, j0, top, pairs.add(second.y, x, pass[1], z[1]));
                    if (pairs.full()) shade_and_merge<WideLanes>(r.calls.quad_rows, shader.self, blend, fb, pairs);
                    return;
                }
                for (int k = 0; k < 2; ++k) {
                    if (!any(pass[k])) continue;
                    groups.add(first.y + k, x, pass[k], z[k]) = interpolate_varyings<L, true>(t, i, k ? j1 : j0);
                    if (groups.full()) shade_and_merge<WideLanes>(r.calls.groups, shader.self, blend, fb, groups);
                }
            });
        }
        return shaded;
    }

    // FragmentQueue: rasterizes the triangle, depth-tests (and writes depth) and queues the
    // fragments that pass; returns the number queued. Coverage comes eight pixels at a time
    // (rasterization_small.h): a small triangle's in 32-bit lanes, a bigger one's with MSAA
    // from each row's spans.
    uint64_t queue_triangle(TriangleSetup<N>& t, const Rect& rect, FragmentQueue<N, Samples>& queue) const requires(kQueueable) {
        using namespace simd;
        const int width = fb.width();
        uint64_t queued = 0;
        queue.begin_triangle(t.front_facing);
        // The triangle may come with its coverage only: its planes are made at its first
        // covered group, so a triangle that covers no sample costs only its edge functions.
        auto need_planes = [&] {
            if (!t.has_planes) setup_planes<Flat>(t);
        };
        // Queues the lanes of `pass`: pixels at (i, j) from the planes' origin, window depths z,
        // index of each pixel's first sample, the samples each writes.
        auto queue_lanes = [&](i8 pass, const f8& i, const f8& j, const f8& z, i8 pixel, i8 samples) {
            queued += unsigned(__builtin_popcount(bits(pass)));
            queue.push(pass, z, interpolate_varyings<L>(t, i, j), pixel, samples);
        };
        // The pixels of group [x, x + 8) of row y: its lanes' places, and its first sample's index.
        auto group_at = [&](int y, int x, f8& i, f8& j) {
            i = to_float(kLaneIndex) + float(x - t.origin_x), j = splat(float(y - t.origin_y));
            return splat_i(int32_t(fb.sample_index(0, y))) + (kLaneIndex + x) * Samples;
        };
        if constexpr (Samples == 1) {
            auto test = [&](int y, int x, i8 covered) {
                need_planes();
                f8 i, j;
                const i8 pixel = group_at(y, x, i, j);
                const f8 z = interpolate_depth(t, i, j);
                const i8 pass = test_group(depth_row(y), x, width, z, covered, t.front_facing);
                if (any(pass)) queue_lanes(pass, i, j, z, pixel, splat_i(1));
            };
            // A triangle up to four pixels wide and eight tall (most of a fine mesh's): its
            // pixels in blocks of 4x2, a block's coverage, depth test and queued group at
            // once. The blocks lie inside the tile, whose pixels are this thread's: a block's
            // lanes outside the triangle have their depth read and written back unchanged.
            // (Not with stencil, whose test_group reads and writes rows of eight.) A triangle
            // of a few narrow rows: a group's coverage at once in 32-bit lanes beats walking
            // each row pixel by pixel; the smallest left, of one to five pixels, are quicker
            // walked (docs/performance.md).
            const int bw = t.bounds.x1 - t.bounds.x0, bh = t.bounds.y1 - t.bounds.y0;
            const int block_rows = (bh + kBlockRows - 1) / kBlockRows * kBlockRows;
            if (bw <= kBlockColumns && bh <= 4 * kBlockRows && !stencil() && rect.x1 - rect.x0 >= kBlockColumns &&
                rect.y1 - rect.y0 >= block_rows && has_small_edges(t)) {
                const int x = std::min(t.bounds.x0, rect.x1 - kBlockColumns), y = std::min(t.bounds.y0, rect.y1 - block_rows);
                rasterize_blocks(t, x, y, [&](int bx, int by, i8 covered) {
                    need_planes();
                    const f8 i = to_float(kBlockColumn) + float(bx - t.origin_x), j = to_float(kBlockRow) + float(by - t.origin_y);
                    const f8 z = interpolate_depth(t, i, j);
                    const size_t at = fb.sample_index(bx, by);
                    const i8 pass = tests.depth.test_block(fb.depth_plane() + at, width, z, covered);
                    if (any(pass)) queue_lanes(pass, i, j, z, splat_i(int32_t(at)) + kBlockColumn + kBlockRow * width, splat_i(1));
                });
            } else if (bw <= kNarrow && bw * bh >= 6 && has_small_edges(t)) {
                rasterize_small<1>(t, [&](int y, int x, const std::array<i8, 1>& covered) { test(y, x, covered[0]); });
            } else {
                rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
                    for_each_group(x_begin, x_end, [&](int x, i8 lanes) { test(y, x, lanes); });
                });
            }
        } else {
            // Four vectors per group in the framebuffer's sample order (GroupSamples<4>): depth
            // at each sample, tested and written, then a mask of passing samples per pixel.
            using G = GroupSamples<Samples>;
            auto test = [&](int y, int x, const std::array<i8, G::kVectors>& covered) {
                need_planes();
                float* depth_row = fb.depth_plane() + fb.sample_index(0, y);
                uint32_t passed = 0;  // Samples bits per pixel
                for (int v = 0; v < G::kVectors; ++v) {
                    // at each sample: the pixel's offset from the origin plus the sample's (exact)
                    const f8 i = to_float(G::pixel(v) + (x - t.origin_x)) + to_float(G::dx(v) - G::pixel(v) * kSubpixelOne32) * (1.0f / 256.0f);
                    const f8 j = float(y - t.origin_y) + to_float(G::dy(v)) * (1.0f / 256.0f);
                    const i8 pass = tests.depth.test_group(depth_row, (x + 2 * v) * Samples, width * Samples, interpolate_depth(t, i, j), covered[size_t(v)]);
                    passed |= bits(pass) << (8 * v);
                }
                if (!passed) return;
                const i8 samples = (splat_i(int32_t(passed)) >> (kLaneIndex * Samples)) & ((1 << Samples) - 1);
                f8 i, j;
                const i8 pixel = group_at(y, x, i, j);
                queue_lanes(samples != 0, i, j, interpolate_depth(t, i, j), pixel, samples);  // (the depth at the pixel center)
            };
            // (Small edges: coverage in 32-bit lanes; else from each row's exact spans.)
            if (has_small_edges(t)) rasterize_small<Samples>(t, test);
            else rasterize_span_groups<Samples>(t, test);
        }
        return queued;
    }
};

}  // namespace softraster
