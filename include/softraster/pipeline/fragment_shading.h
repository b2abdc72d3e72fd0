// Stage 8, fragment shading: run the user's fragment shader for a pixel, then merge.
//
// The depth test runs before the shader (early-Z). That is invisible to the picture because
// shaders here cannot change depth, and a discarded fragment writes nothing either way; it
// saves the whole shading cost of hidden fragments. With MSAA the shader runs once per pixel,
// at the pixel center, and its color goes to every covered sample that passed.
#pragma once
#include "softraster/framebuffer.h"
#include "softraster/pipeline/fragment_queue.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/rasterization_small.h"
#include "softraster/pipeline/shader.h"

namespace softraster {

// Depth-tests samples `covered` of pixel (x, y) at depths z, and if any pass, shades the
// fragment with the varyings that make_varyings() returns and merges it.
template <int Samples, BlendMode B, Shader S, class MakeVaryings>
inline void shade_fragment(const S& shader, const RenderState& st, Framebuffer& fb, int x, int y,
                           unsigned covered, const float* z, float center_z, bool front_facing,
                           MakeVaryings&& make_varyings, uint64_t& shaded) {
    const size_t base = fb.sample_index(x, y);
    const unsigned pass = depth_test<Samples>(st, fb.depth_data() + base, covered, z);
    if (!pass) return;
    ++shaded;
    const typename S::Varyings v = make_varyings();
    const FragCoord frag{float(x) + 0.5f, float(y) + 0.5f, center_z, front_facing};
    glm::vec4 color;
    if (!shader.fragment(v, frag, color)) return;
    merge_fragment<Samples, B>(st, fb.color_data() + base, fb.depth_data() + base, pass, z, color);
}

// Rasterizes one set-up triangle (within its bounds) and shades what it covers; returns the
// number of fragments shaded.
template <int Samples, BlendMode B, Shader S>
uint64_t draw_triangle(const S& shader, const RenderState& st, Framebuffer& fb,
                       const TriangleSetup<kVaryingCount<typename S::Varyings>>& t) {
    using V = typename S::Varyings;
    uint64_t shaded = 0;
    rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
        const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // shaded at the pixel center
        shade_fragment<Samples, B>(shader, st, fb, px.x, px.y, px.mask, px.z.data(), interpolate_depth(t, i, j),
                                   t.front_facing, [&] { return from_array<V>(interpolate_perspective(t, i, j)); }, shaded);
    });
    return shaded;
}

// ---- eight pixels at once
//
// A shader can also offer fragment_batch(varyings, z, front_facing, color): the same
// formulas on eight pixels of a row, one simd::f8 per varying and per color channel. For
// single-sampled targets the triangle is then walked in row spans, eight pixels at a time:
// depth, 1/w and every varying are evaluated from their planes for eight pixels at once,
// tested, shaded and blended as vectors.
template <class S>
concept BatchShader = Shader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v,
                                           simd::f8 z, std::array<simd::f8, 4>& color) {
    s.fragment_batch(v, z, true, color);
};

template <BlendMode B, BatchShader S>
uint64_t draw_triangle_batched(const S& shader, const RenderState& st, Framebuffer& fb,
                               const TriangleSetup<kVaryingCount<typename S::Varyings>>& t) {
    using namespace simd;
    uint64_t shaded = 0;
    rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
        const f8 j = splat(float(y - t.origin_y));
        float* depth = fb.depth_data() + fb.sample_index(0, y);
        Rgba8* color = fb.color_data() + fb.sample_index(0, y);
        const int width = fb.width();
        for_each_group(x_begin, x_end, [&](int x, i8 pass) {
            const f8 i = to_float(kLaneIndex) + float(x - t.origin_x);
            const f8 z = interpolate_depth(t, i, j);
            f8 stored{};
            if (st.depth_test) {
                stored = load_group<f8>(depth, x, width);
                pass &= depth_passes(st.depth_func, z, stored);
            }
            if (!any(pass)) return;
            std::array<f8, 4> rgba;
            shader.fragment_batch(interpolate_perspective(t, i, j), z, t.front_facing, rgba);
            shaded += unsigned(__builtin_popcount(bits(pass)));
            if (st.depth_test && st.depth_write) store_group(depth, x, width, select(pass, z, stored));
            if (st.color_write) blend_group<B>(color, x, width, pass, rgba);
        });
    });
    return shaded;
}


// ---- depth-test now, shade later in full groups (fragment_queue.h)

// Rasterizes one set-up triangle, depth-tests and writes depth, and queues the fragments
// that pass; returns the number queued. For draws the queue allows (opaque, pure shader,
// color writes on). Small triangles are covered eight pixels at a time (rasterization_small.h).
template <int Samples, BatchShader S>
uint64_t queue_triangle(const RenderState& st, Framebuffer& fb, TriangleSetup<kVaryingCount<typename S::Varyings>>& t,
                        FragmentQueue<S, Samples>& queue) {
    using namespace simd;
    const int width = fb.width();
    uint64_t queued = 0;
    // The triangle may come with its coverage only: its planes are made at its first covered
    // group, so a triangle that covers no sample costs no more than its edge functions.
    auto need_planes = [&] {
        if (!t.has_planes) setup_planes(t);
    };
    // Queues the pixels of group [x, x + 8) of row y set in `pass`, writing `samples` of each.
    auto queue_group = [&](int y, int x, i8 pass, i8 samples) {
        const f8 i = to_float(kLaneIndex) + float(x - t.origin_x), j = splat(float(y - t.origin_y));
        queued += unsigned(__builtin_popcount(bits(pass)));
        const i8 pixel = (splat_i(int32_t(fb.sample_index(0, y))) + (kLaneIndex + x) * Samples);
        queue.push(pass, interpolate_depth(t, i, j), interpolate_perspective(t, i, j), pixel, samples, t.front_facing);
    };
    if constexpr (Samples == 1) {
        // Depth test of the covered pixels of group [x, x + 8) of row y, then queueing.
        auto test_group = [&](int y, int x, i8 pass) {
            need_planes();
            if (st.depth_test) {
                float* depth = fb.depth_data() + fb.sample_index(0, y);
                const f8 z = interpolate_depth(t, to_float(kLaneIndex) + float(x - t.origin_x), splat(float(y - t.origin_y)));
                const f8 stored = load_group<f8>(depth, x, width);
                pass &= depth_passes(st.depth_func, z, stored);
                if (!any(pass)) return;
                if (st.depth_write) store_group(depth, x, width, select(pass, z, stored));
            }
            queue_group(y, x, pass, splat_i(1));
        };
        // A triangle of a few narrow rows: a group's coverage at once in 32-bit lanes
        // (rasterization_small.h) beats walking each row pixel by pixel (bench_many_objects
        // -2.5%); the smallest, of one to five pixels, are quicker walked (given the lanes
        // too, bench_highpoly_480 took 3-5% longer).
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
            float* depth = fb.depth_data() + fb.sample_index(0, y);
            uint32_t passed = 0;  // 4 bits per pixel
            for (int v = 0; v < G::kVectors; ++v) {
                i8 pass = covered[size_t(v)];
                if (st.depth_test) {
                    // at each sample: the pixel's offset from the origin plus the sample's (exact)
                    const f8 i = to_float(G::pixel(v) + (x - t.origin_x)) + to_float(G::dx(v) - G::pixel(v) * kSubpixelOne32) * (1.0f / 256.0f);
                    const f8 j = float(y - t.origin_y) + to_float(G::dy(v)) * (1.0f / 256.0f);
                    const f8 z = interpolate_depth(t, i, j);
                    const int at = (x + 2 * v) * Samples, row_width = width * Samples;
                    const f8 stored = load_group<f8>(depth, at, row_width);
                    pass &= depth_passes(st.depth_func, z, stored);
                    if (st.depth_write) store_group(depth, at, row_width, select(pass, z, stored));
                }
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
            float* depth = fb.depth_data() + base;
            const unsigned pass = depth_test<Samples>(st, depth, px.mask, px.z.data());
            if (!pass) return;
            if (st.depth_test && st.depth_write)
                for (int s = 0; s < Samples; ++s)
                    if (pass & (1u << s)) depth[s] = px.z[size_t(s)];
            const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // shaded at the pixel center
            ++queued;
            queue.push(interpolate_depth(t, i, j), interpolate_perspective(t, i, j), int32_t(base), pass, t.front_facing);
        });
    }
    return queued;
}

}  // namespace softraster
