// The general tile back end: draws whose state the fast back end (tile_back_end.h) does not
// handle (a stencil test, a partial color mask, alpha cutoff, alpha-to-coverage, 2, 8 or
// 16 samples; see needs_general_back_end in render_state.h), one
// fragment at a time, with every per-fragment operation in OpenGL's order:
//   fragment shader -> alpha cutoff (discard) -> alpha-to-coverage -> stencil test ->
//   depth test -> stencil operations and depth write -> blending, under the color mask.
// When nothing but the two tests can drop a fragment (a shader that never discards, no
// cutoff, no alpha-to-coverage), the tests run first and only the fragments that pass are
// shaded ("early" tests, as GPUs do): the same picture for less work.
//
// Single-sampled opaque draws of a batch shader whose tests can run early (a stencil test)
// take the fast back end instead, with DepthStencilTest as its depth stage
// (GeneralTriangleCommand in draw_commands.h).
//
// To keep the build small this back end is compiled once per varying layout
// (shader_layout.h): the sample count is a run-time value, and only rasterization, the same
// for every layout of a varying count, is compiled per count.
#pragma once
#include <array>
#include <cstdint>
#include <utility>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binned_triangles.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/render_state.h"

namespace softraster {

inline constexpr int kMaxSamples = 16;

// Calls f.template operator()<Samples>() with a valid run-time sample count as a constant.
template <class F>
decltype(auto) with_sample_count(int samples, F&& f) {
    switch (samples) {
        case 2: return f.template operator()<2>();
        case 4: return f.template operator()<4>();
        case 8: return f.template operator()<8>();
        case 16: return f.template operator()<16>();
        default: return f.template operator()<1>();
    }
}

// A non-owning reference to a callable (C++26's std::function_ref): one indirect call, no
// allocation. It lets the rasterizer below be compiled once for all shaders.
template <class Signature>
class FunctionRef;
template <class R, class... Args>
class FunctionRef<R(Args...)> {
public:
    template <class F>
    FunctionRef(F& f) : object_(&f), call_([](void* o, Args... a) -> R { return (*static_cast<F*>(o))(std::forward<Args>(a)...); }) {}
    R operator()(Args... a) const { return call_(object_, std::forward<Args>(a)...); }

private:
    void* object_;
    R (*call_)(void*, Args...);
};

// One pixel of a triangle: its covered samples and their depths.
struct PixelSamples {
    int x = 0, y = 0;
    unsigned mask = 0;
    std::array<float, kMaxSamples> z{};
};

// The per-fragment operations of one draw, ready to run.
struct FragmentOps {
    DepthStencilTest tests;
    BlendSettings blend;
    int samples = 1;
    bool alpha_test = false;
    float alpha_cutoff = 0.5f;
    bool alpha_to_coverage = false;
    bool early = false;  // the tests before the shader

    FragmentOps(const RenderState& st, int sample_count, bool shader_may_discard, ColorSpace color = ColorSpace::Linear)
        : tests(st), blend(st, color), samples(sample_count), alpha_test(st.alpha_test), alpha_cutoff(st.alpha_cutoff),
          alpha_to_coverage(st.alpha_to_coverage && sample_count > 1),
          early(!shader_may_discard && !alpha_test && !alpha_to_coverage) {}
};

// Alpha-to-coverage: sample s of n stays covered when alpha > s / n, so alpha spreads over
// the samples in steps of 1/n (llvmpipe's rule, without dithering).
inline unsigned alpha_coverage(float alpha, int samples) {
    unsigned mask = 0;
    const float step = 1.0f / float(samples);
    for (int s = 0; s < samples; ++s)
        if (alpha > step * float(s)) mask |= 1u << s;
    return mask;
}

// One fragment of pixel (x, y) whose samples `covered` lie at depths z: every per-fragment
// operation (see the top of this file); the shader gets the varyings make_varyings() returns.
template <int N, class MakeVaryings>
void general_fragment(const FragmentCalls<N>& calls, const void* shader, const FragmentOps& ops, Framebuffer& fb, int x, int y, unsigned covered, const float* z,
                      float center_z, bool front_facing, MakeVaryings&& make_varyings, uint64_t& shaded) {
    const size_t base = fb.sample_index(x, y);
    float* depth = fb.depth_plane() + base;
    uint8_t* stencil = fb.has_stencil() ? fb.stencil_plane() + base : nullptr;
    unsigned pass = covered;
    if (ops.early) {
        pass = ops.tests.test_and_write(depth, stencil, ops.samples, covered, z, front_facing);
        if (!pass || !ops.blend.color_mask) return;  // (no color to write: the shader's result would go nowhere)
    }
    ++shaded;
    glm::vec4 color;
    if (!calls.pixel(shader, make_varyings(), FragCoord{float(x) + 0.5f, float(y) + 0.5f, center_z, front_facing}, color)) return;
    if (!ops.early) {
        if (ops.alpha_test && color.a < ops.alpha_cutoff) return;
        if (ops.alpha_to_coverage) pass &= alpha_coverage(color.a, ops.samples);
        pass = ops.tests.test_and_write(depth, stencil, ops.samples, pass, z, front_facing);
        if (!pass) return;
    }
    if (!ops.blend.color_mask) return;
    Rgba8* c = fb.color_plane() + base;
    if (ops.blend.replace) {  // quantized once for all samples, no blend arithmetic
        const Rgba8 q = quantize_rgba8(color, ops.blend.color_space);
        for (int s = 0; s < ops.samples; ++s)
            if (pass & (1u << s)) c[s] = q;
        return;
    }
    for (int s = 0; s < ops.samples; ++s)
        if (pass & (1u << s)) c[s] = blend(ops.blend, color, c[s]);
}

// Calls on_pixel(setup, pixel) for every covered pixel of the draw's triangles in tile
// (tx, ty) within `rect`, in draw order, for a framebuffer of `samples` samples. Compiled per
// varying count, not per shader.
template <uint64_t Flat, int N>
void rasterize_tile(int samples, const BinnedTriangles<N>& triangles, const RenderState& state, int tx, int ty, const Rect& rect,
                    FunctionRef<void(const TriangleSetup<N>&, const PixelSamples&)> on_pixel) {
    with_sample_count(samples, [&]<int Samples>() {
        PixelSamples out;
        for_each_triangle_setup<Samples, true, Flat>(triangles, state, tx, ty, rect, [&](const TriangleSetup<N>& setup, uint32_t) {
            rasterize_triangle<Samples>(setup, setup.bounds, [&](const CoveredPixel<Samples>& px) {
                out.x = px.x;
                out.y = px.y;
                out.mask = px.mask;
                std::copy(px.z.begin(), px.z.end(), out.z.begin());
                on_pixel(setup, out);
            });
        });
    });
}

// The draw's triangles in one tile (`rect`, already cut to the scissor); returns the
// fragments shaded.
template <class L>
uint64_t draw_tile_general(const LayoutShader<L>& shader, const FragmentOps& ops, const RenderState& state,
                           const BinnedTriangles<L::N>& triangles, Framebuffer& fb, int tx, int ty, const Rect& rect) {
    constexpr int N = L::N;
    // (This back end has one copy; the shader's AVX2 one where the CPU has it, as the fast back end's.)
    const FragmentCalls<N>& calls = shader.code->path(simd::wide_path_runs());
    uint64_t shaded = 0;
    auto on_pixel = [&](const TriangleSetup<N>& t, const PixelSamples& px) {
        const float i = float(px.x - t.origin_x), j = float(px.y - t.origin_y);  // the pixel center
        general_fragment(calls, shader.self, ops, fb, px.x, px.y, px.mask, px.z.data(), interpolate_depth(t, i, j), t.front_facing,
                         [&] { return interpolate_varyings<L>(t, i, j); }, shaded);
    };
    rasterize_tile<L::kFlat, N>(ops.samples, triangles, state, tx, ty, rect, on_pixel);
    return shaded;
}

}  // namespace softraster
