// The tile back end: one draw's triangles in one tile, each through the per-pixel stages
// in order:
//   triangle setup (triangle_setup.h) -> rasterization (rasterization.h, and
//   rasterization_small.h for small triangles) -> early depth test (depth_stencil.h) ->
//   interpolation (interpolation.h) -> fragment shading (fragment_shading.h, through the
//   fragment queue of fragment_queue.h for small triangles) -> output merge (output_merge.h).
// The tile's thread runs the draws of the tile one after another, in draw order
// (Context::execute); runs of opaque draws with heavy overdraw take two passes instead
// (hidden_surface_removal.h).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <type_traits>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/fragment_queue.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/rasterization_small.h"
#include "softraster/pipeline/triangle_setup.h"
#include "softraster/render_state.h"

namespace softraster {

// A draw's triangles as binning left them: its chunks' bins and its post-transform vertices.
template <int N>
struct BinnedTriangles {
    std::span<const TriangleBin<N>> bins;
    const ShadedVertex<N>* post = nullptr;
};

// Calls f(setup, ordinal) for each of the draw's triangles in tile (tx, ty), whose pixels
// are `rect`, in draw order; the ordinal counts them (hidden_surface_removal.h names a
// triangle by it). Without Planes, the setup has its coverage only (f makes the planes
// when it needs them).
template <int Samples, bool Planes = true, uint64_t Flat = 0, bool Constant = false, int N, class F>
void for_each_triangle_setup(const BinnedTriangles<N>& draw, const RenderState& state, int tx, int ty, const Rect& rect, F&& f) {
    TriangleSetup<N> setup;
    setup.options = PlaneOptions::of(state);
    const FrontFace front = state.front_face;
    uint32_t ordinal = 0;
    // Setup reads the window position and varyings of three vertices anywhere in the
    // draw's vertex buffer: fetch those of a triangle a few places ahead into the cache
    // while this one is drawn, or the loads wait on memory.
    constexpr size_t kAhead = 4;
    for (const TriangleBin<N>& bin : draw.bins) {
        const std::span<const TriangleRef> refs = bin.triangles_in(tx, ty);
        // (Only vertices of the post-transform buffer: the few the clipper made sit in a
        // short list of their own. GCC 12 drops a prefetch whose address is chosen by a
        // condition, as bin.vertex() chooses between the two lists.)
        auto prefetch = [&](const TriangleRef& r) {
            for (uint32_t i : r.v) {
                if (i & kClippedVertex) continue;
                const char* v = reinterpret_cast<const char*>(draw.post + i);
                __builtin_prefetch(v);  // at most two cache lines
                __builtin_prefetch(v + sizeof(ShadedVertex<N>) - 1);
            }
        };
        for (size_t a = 1; a < std::min(refs.size(), kAhead); ++a) prefetch(refs[a]);
        for (size_t k = 0; k < refs.size(); ++k, ++ordinal) {
            if (k + kAhead < refs.size()) prefetch(refs[k + kAhead]);
            const TriangleRef& r = refs[k];
            if (setup_coverage<Samples>(bin.vertex(r.v[0], draw.post), bin.vertex(r.v[1], draw.post),
                                        bin.vertex(r.v[2], draw.post), front, rect, setup)) {
                if constexpr (Planes) setup_planes<Flat, Constant>(setup);
                f(setup, ordinal);
            }
        }
    }
}

template <Shader S, int Samples, bool Blended, class DepthStencil = DepthTest>
struct TileBackEnd {
    static constexpr int N = kVaryingCount<typename S::Varyings>;
    static constexpr uint64_t Flat = kFlatVaryings<S>;
    // Blended draws of shaders that read varyings alone shade a triangle whose varyings are
    // constant once (draw_groups); setup looks for those only in them (setup_planes).
    static constexpr bool kConstant = Blended && VaryingsOnlyShader<S>;
    using V = typename S::Varyings;
    // Draws that test stencil (general_back_end.h sends the single-sampled opaque ones here)
    // run the fragment queue or EightPixelGroups, with the stencil test where depth is tested.
    static constexpr bool kStencil = std::is_same_v<DepthStencil, DepthStencilTest>;

    // By value, not by reference: the tile loops read them after every framebuffer store,
    // which may alias anything, so each reference would cost another load there.
    S shader;
    RenderState state;
    DepthStencil depth;
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
    //   pixels, were faster, and without it each model's draws compile in a fifth less time
    //   (docs/performance.md: the fragment queue, and "Build time").
    enum class Strategy { FragmentQueue, EightPixelGroups, PixelByPixel };
    static constexpr bool kQueueable = BatchShader<S> && PureShader<S> && !Blended;
    Strategy strategy() const {
        if (kQueueable && state.color_write && blend.color_mask) return Strategy::FragmentQueue;
        return Samples == 1 && BatchShader<S> ? Strategy::EightPixelGroups : Strategy::PixelByPixel;
    }

    // Draws the draw's triangles in tile (tx, ty), whose pixels are `rect`; returns the
    // fragments shaded. WideLanes: compiled for AVX2, where eight lanes are one register.
    template <bool WideLanes>
    uint64_t draw(int tx, int ty, const Rect& rect) const {
        uint64_t shaded = 0;
        if constexpr (kQueueable && WideLanes) {
            if (strategy() == Strategy::FragmentQueue) {
                // One queue per thread, off the stack: a few kilobytes that would otherwise
                // sit among the tile loop's spilled registers.
                static thread_local FragmentQueue<S, Samples> queue;
                queue.start(shader, fb);
                for_each_triangle_setup<Samples, /*Planes=*/false, Flat, kConstant>(triangles, state, tx, ty, rect,
                                                                   [&](TriangleSetup<N>& setup, uint32_t) {
                    if constexpr (Samples == 1) {  // (else draw_groups would be compiled, never to run)
                        if (is_large(setup.bounds)) {
                            queue.flush();
                            setup_planes<Flat, kConstant>(setup);
                            shaded += draw_groups(setup);
                            return;
                        }
                    }
                    shaded += queue_triangle(setup, queue);  // makes the planes if needed
                });
                queue.flush();
                return shaded;
            }
        }
        for_each_triangle_setup<Samples, true, Flat, kConstant>(triangles, state, tx, ty, rect, [&](const TriangleSetup<N>& setup, uint32_t) {
            if constexpr (Samples == 1 && BatchShader<S>) {
                if (kStencil || WideLanes || setup.bounds.x1 - setup.bounds.x0 >= 16) {  // EightPixelGroups
                    shaded += draw_groups(setup);
                    return;
                }
            }
            if constexpr (!kStencil) shaded += draw_pixels(setup);
        });
        return shaded;
    }

    // A triangle at least this big in the tile fills its groups of eight without the queue.
    static bool is_large(const Rect& r) { return (r.x1 - r.x0) >= 32 && (r.y1 - r.y0) >= 16; }

    // PixelByPixel: each covered pixel's samples, depth-tested, shaded at the pixel center
    // and merged.
    uint64_t draw_pixels(const TriangleSetup<N>& t) const {
        uint64_t shaded = 0;
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
            const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // the pixel center
            shade_fragment<Samples, Blended>(shader, depth, blend, fb, px.x, px.y, px.mask, px.z.data(),
                                       interpolate_depth(t, i, j), t.front_facing,
                                       [&] { return from_array<V>(interpolate_varyings<S, kConstant>(t, i, j)); }, shaded);
        });
        return shaded;
    }

    // EightPixelGroups: each row's span in groups of eight; depth, 1/w and the varyings
    // from their planes for eight pixels at once.
    uint64_t draw_groups(const TriangleSetup<N>& t) const requires(BatchShader<S>) {
        using namespace simd;
        uint64_t shaded = 0;
        const int width = fb.width();
        // Constant varyings and a shader that reads nothing else: one color for the whole
        // triangle, shaded here once.
        std::array<f8, 4> constant_rgba{};
        bool shaded_once = false;
        if constexpr (kConstant) {
            if (t.constant_varyings) {
                run_fragment_batch(shader, interpolate_varyings<S, kConstant>(t, splat(0.0f), splat(0.0f)), splat(0.0f), t.front_facing,
                                   constant_rgba);
                shaded_once = true;
            }
        }
        auto shade = [&](f8 i, f8 j, f8 z, std::array<f8, 4>& rgba) {
            if constexpr (kConstant) {
                if (shaded_once) {
                    rgba = constant_rgba;
                    return;
                }
            }
            run_fragment_batch(shader, interpolate_varyings<S, kConstant>(t, i, j), z, t.front_facing, rgba);
        };
        auto row = [&](int y, int x_begin, int x_end) {
            const f8 j = splat(float(y - t.origin_y));
            float* depth_row = fb.depth_data() + fb.sample_index(0, y);
            Rgba8* color_row = fb.color_data() + fb.sample_index(0, y);
            RowGroups pending;  // (Custom blending only)
            for_each_group(x_begin, x_end, [&](int x, i8 covered) {
                const f8 i = to_float(kLaneIndex) + float(x - t.origin_x);
                const f8 z = interpolate_depth(t, i, j);
                i8 pass;
                if constexpr (kStencil) {
                    pass = depth.test_group(depth_row, fb.stencil_data() + fb.sample_index(0, y), x, width, z, covered, t.front_facing);
                } else {
                    pass = depth.test_group(depth_row, x, width, z, covered);
                }
                if (!any(pass)) return;
                if (!blend.color_mask) return;  // (a stencil or depth pass only: no fragment to shade)
                shaded += unsigned(__builtin_popcount(bits(pass)));
                if constexpr (Blended) {
                    if (blend.mode == BlendMode::Custom) {  // shaded now, blended with the row's other groups
                        std::array<f8, 4> rgba;
                        shade(i, j, z, rgba);
                        simd::i8 packed;
                        quantize_pack_rgba8(rgba, packed);
                        pending.add(x, pass, packed);
                        return;
                    }
                }
                std::array<f8, 4> rgba;
                shade(i, j, z, rgba);
                blend_group<Blended>(blend, color_row, x, width, pass, rgba);
            });
            if constexpr (Blended) {
                if (pending.count > 0) blend_row(blend, color_row, width, pending);
            }
        };
        if constexpr (QuadRowShader<S> && DerivativeShader<S> && !kStencil) {
            // A shader that shades two rows of quads at once (QuadRowShader) gets the groups
            // of a quads' first row (y even) and of the row below together, the first row's
            // span held until the second's comes. Each pixel's depth test, color and merge
            // are its own, so the order between the two rows changes nothing.
            const bool pairs = !(Blended && blend.mode == BlendMode::Custom) && !shaded_once && blend.color_mask;
            if (pairs) {
                int held_y = -1, held_begin = 0, held_end = 0;  // a first row's span, waiting
                rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
                    if (held_y >= 0 && held_y == y - 1) {
                        shaded += draw_quad_rows(t, held_y, held_begin, held_end, x_begin, x_end);
                        held_y = -1;
                        return;
                    }
                    if (held_y >= 0) row(held_y, held_begin, held_end), held_y = -1;
                    if ((y & 1) == 0) held_y = y, held_begin = x_begin, held_end = x_end;
                    else row(y, x_begin, x_end);
                });
                if (held_y >= 0) row(held_y, held_begin, held_end);
                return shaded;
            }
        }
        rasterize_spans(t, t.bounds, row);
        return shaded;
    }

    // The groups of rows y (a quads' first) and y + 1, spans [begin0, end0) and [begin1,
    // end1): where both rows of a group have pixels that pass the depth test, shaded with one
    // call (QuadRowShader), and two such neighbouring groups with one call where the shader
    // takes four (QuadBlockShader: the first is held until the next comes); else each row's
    // on its own. Each pixel's depth test, color and merge are its own, so the order between
    // the groups changes nothing.
    uint64_t draw_quad_rows(const TriangleSetup<N>& t, int y, int begin0, int end0, int begin1, int end1) const
        requires(QuadRowShader<S> && DerivativeShader<S>) {
        using namespace simd;
        uint64_t shaded = 0;
        const int width = fb.width();
        const f8 j0 = splat(float(y - t.origin_y)), j1 = splat(float(y + 1 - t.origin_y));
        float* depth_rows[2] = {fb.depth_data() + fb.sample_index(0, y), fb.depth_data() + fb.sample_index(0, y + 1)};
        Rgba8* color_rows[2] = {fb.color_data() + fb.sample_index(0, y), fb.color_data() + fb.sample_index(0, y + 1)};
        // A group whose two rows both have pixels to shade: its x, lane offsets, depths and
        // passing lanes per row. (The lanes are whole quads: x is a multiple of 8 and y even;
        // draw_groups pairs no triangle whose varyings are constant.)
        struct Pair {
            int x;
            f8 i, z[2];
            i8 pass[2];
        };
        auto merge = [&](int x, const i8* pass, const std::array<f8, 4>* rgba) {  // (pass[r], rgba[r]: row r's)
            for (int r = 0; r < 2; ++r) blend_group<Blended>(blend, color_rows[r], x, width, pass[r], rgba[r]);
        };
        auto shade_pair = [&](const Pair& p) {
            std::array<f8, N> v[2];
            interpolate_quad_row_pair<S>(t, p.i, j0, v[0], v[1]);
            std::array<f8, 4> rgba[2];
            run_fragment_quad_rows(shader, v[0], v[1], p.z[0], p.z[1], t.front_facing, rgba[0], rgba[1]);
            merge(p.x, p.pass, rgba);
        };
        Pair held{};
        bool holding = false;
        for_each_group(std::min(begin0, begin1), std::max(end0, end1), [&](int x, i8) {
            const i8 px = kLaneIndex + x;
            const i8 covered[2] = {(px >= begin0) & (px < end0), (px >= begin1) & (px < end1)};
            const f8 i = to_float(kLaneIndex) + float(x - t.origin_x);
            const f8 z[2] = {interpolate_depth(t, i, j0), interpolate_depth(t, i, j1)};
            i8 pass[2];
            for (int r = 0; r < 2; ++r) pass[r] = any(covered[r]) ? depth.test_group(depth_rows[r], x, width, z[r], covered[r]) : splat_i(0);
            shaded += unsigned(__builtin_popcount(bits(pass[0]))) + unsigned(__builtin_popcount(bits(pass[1])));
            if (any(pass[0]) && any(pass[1])) {
                if constexpr (QuadBlockShader<S>) {
                    if (!holding || held.x != x - kLanes) {  // (a held group not next to this one goes alone)
                        if (holding) shade_pair(held);
                        held = {x, i, {z[0], z[1]}, {pass[0], pass[1]}}, holding = true;
                        return;
                    }
                    holding = false;
                    std::array<f8, N> v[4];
                    interpolate_quad_row_pair<S>(t, held.i, j0, v[0], v[1]);
                    interpolate_quad_row_pair<S>(t, i, j0, v[2], v[3]);
                    const f8 zs[4] = {held.z[0], held.z[1], z[0], z[1]};
                    std::array<f8, 4> rgba[4];
                    run_fragment_quad_block(shader, v, zs, t.front_facing, rgba);
                    merge(held.x, held.pass, &rgba[0]);
                    merge(x, pass, &rgba[2]);
                    return;
                } else {
                    shade_pair({x, i, {z[0], z[1]}, {pass[0], pass[1]}});
                    return;
                }
            }
            if (holding) shade_pair(held), holding = false;
            std::array<f8, 4> rgba[2];
            for (int r = 0; r < 2; ++r)
                if (any(pass[r])) run_fragment_batch(shader, interpolate_varyings<S, kConstant>(t, i, r ? j1 : j0), z[r], t.front_facing, rgba[r]);
            for (int r = 0; r < 2; ++r)
                if (any(pass[r])) blend_group<Blended>(blend, color_rows[r], x, width, pass[r], rgba[r]);
        });
        if (holding) shade_pair(held);
        return shaded;
    }

    // FragmentQueue: rasterizes the triangle, depth-tests (and writes depth) and queues the
    // fragments that pass; returns the number queued. Small triangles' coverage comes eight
    // pixels at a time in 32-bit lanes (rasterization_small.h).
    uint64_t queue_triangle(TriangleSetup<N>& t, FragmentQueue<S, Samples>& queue) const requires(kQueueable) {
        using namespace simd;
        const int width = fb.width();
        uint64_t queued = 0;
        // The triangle may come with its coverage only: its planes are made at its first
        // covered group, so a triangle that covers no sample costs only its edge functions.
        auto need_planes = [&] {
            if (!t.has_planes) setup_planes<Flat, kConstant>(t);
        };
        // Queues the pixels of group [x, x + 8) of row y set in `pass`, writing `samples` of each.
        auto queue_group = [&](int y, int x, i8 pass, i8 samples) {
            const f8 i = to_float(kLaneIndex) + float(x - t.origin_x), j = splat(float(y - t.origin_y));
            queued += unsigned(__builtin_popcount(bits(pass)));
            const i8 pixel = (splat_i(int32_t(fb.sample_index(0, y))) + (kLaneIndex + x) * Samples);
            queue.push(pass, interpolate_depth(t, i, j), interpolate_varyings<S, kConstant>(t, i, j), pixel, samples, t.front_facing);
        };
        if constexpr (Samples == 1) {
            auto test_group = [&](int y, int x, i8 covered) {
                need_planes();
                const f8 z = interpolate_depth(t, to_float(kLaneIndex) + float(x - t.origin_x), splat(float(y - t.origin_y)));
                float* depth_row = fb.depth_data() + fb.sample_index(0, y);
                i8 pass;
                if constexpr (kStencil) {
                    pass = depth.test_group(depth_row, fb.stencil_data() + fb.sample_index(0, y), x, width, z, covered, t.front_facing);
                } else {
                    pass = depth.test_group(depth_row, x, width, z, covered);
                }
                if (any(pass)) queue_group(y, x, pass, splat_i(1));
            };
            // A triangle of a few narrow rows: a group's coverage at once in 32-bit lanes
            // beats walking each row pixel by pixel; the smallest, of one to five pixels,
            // are quicker walked (docs/performance.md).
            const int bw = t.bounds.x1 - t.bounds.x0, bh = t.bounds.y1 - t.bounds.y0;
            if (bw <= kNarrow && bw * bh >= 6 && has_small_edges(t)) {
                rasterize_small<1>(t, [&](int y, int x, const std::array<i8, 1>& covered) { test_group(y, x, covered[0]); });
            } else {
                rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
                    for_each_group(x_begin, x_end, [&](int x, i8 lanes) { test_group(y, x, lanes); });
                });
            }
        } else if (has_small_edges(t)) {
            // Four vectors per group in the framebuffer's sample order (GroupSamples<4>): depth
            // at each sample, tested and written, then a mask of passing samples per pixel.
            using G = GroupSamples<Samples>;
            rasterize_small<Samples>(t, [&](int y, int x, const std::array<i8, G::kVectors>& covered) {
                need_planes();
                float* depth_row = fb.depth_data() + fb.sample_index(0, y);
                uint32_t passed = 0;  // Samples bits per pixel
                for (int v = 0; v < G::kVectors; ++v) {
                    // at each sample: the pixel's offset from the origin plus the sample's (exact)
                    const f8 i = to_float(G::pixel(v) + (x - t.origin_x)) + to_float(G::dx(v) - G::pixel(v) * kSubpixelOne32) * (1.0f / 256.0f);
                    const f8 j = float(y - t.origin_y) + to_float(G::dy(v)) * (1.0f / 256.0f);
                    const i8 pass = depth.test_group(depth_row, (x + 2 * v) * Samples, width * Samples, interpolate_depth(t, i, j), covered[size_t(v)]);
                    passed |= bits(pass) << (8 * v);
                }
                if (!passed) return;
                const i8 samples = (splat_i(int32_t(passed)) >> (kLaneIndex * Samples)) & ((1 << Samples) - 1);
                queue_group(y, x, samples != 0, samples);
            });
        } else {
            need_planes();  // (this rasterizer interpolates depth itself)
            rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
                const size_t base = fb.sample_index(px.x, px.y);
                const unsigned pass = depth.template test_and_write_pixel<Samples>(fb.depth_data() + base, px.mask, px.z.data());
                if (!pass) return;
                const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // the pixel center
                ++queued;
                queue.push(interpolate_depth(t, i, j), interpolate_varyings<S, kConstant>(t, i, j), int32_t(base), pass, t.front_facing);
            });
        }
        return queued;
    }
};

}  // namespace softraster
