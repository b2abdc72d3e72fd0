// Stage 8, fragment shading: the user's fragment shader, for one pixel or for eight.
//
// With MSAA the shader runs once per pixel, at the pixel center, and its color goes to every
// covered sample that passed the depth test. A shader may also offer
// fragment_batch(varyings, z, front_facing, color): the same formulas on eight pixels at
// once, one simd::f8 per varying and per color channel (BatchShader); the back end then
// shades eight pixels of a row, or eight queued fragments (fragment_queue.h), per call.
#pragma once
#include <array>
#include <cstdint>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

template <class S>
concept BatchShader = Shader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v,
                                           simd::f8 z, std::array<simd::f8, 4>& color) {
    s.fragment_batch(v, z, true, color);
};

// A shader may also offer fragment_quad_rows(v0, v1, z0, z1, front_facing, color0, color1):
// fragment_batch for the two rows of a row of 2x2 quads (eight pixels of a quads' first row
// and the eight below them) at once, where doing both together is cheaper (a texture's
// lookups: one level of detail for both). The back end then shades such pairs with one call.
template <class S>
concept QuadRowShader = BatchShader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v,
                                                   simd::f8 z, std::array<simd::f8, 4>& color) {
    s.fragment_quad_rows(v, v, z, z, true, color, color);
};

// And fragment_quad_block(v, z, front_facing, color), v, z and color arrays of four: two
// neighbouring pairs as fragment_quad_rows takes them (groups 0 and 1 the first pair's rows,
// 2 and 3 the next eight pixels' to the right), where four together are cheaper still.
template <class S>
concept QuadBlockShader = QuadRowShader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>> (&v)[4],
                                                       const simd::f8 (&z)[4], std::array<simd::f8, 4> (&color)[4]) {
    s.fragment_quad_block(v, z, true, color);
};

// A shader that never discards and has no side effects says so with
// `static constexpr bool kPure = true;`: its fragments' depth can be written before they
// are shaded, and they can be shaded in any order (fragment_queue.h,
// hidden_surface_removal.h).
template <class S>
concept PureShader = requires { requires S::kPure; };

// A shader whose fragment code is long (lighting, several textures) says so with
// `static constexpr bool kOutOfLine = true;`: the back ends then call it out of line,
// compiled once per shader (in each CPU path's copy, on_best_path), instead of inlining it
// into every back-end copy that shades (per sample count and blending, the hidden-surface
// pass, the general back end). A call per eight fragments costs little next to such a
// shader, and those inlined copies were most of the build; a short shader stays inline,
// where the call would cost as much as its work (docs/performance.md, "Build time").
template <class S>
concept OutOfLineShader = requires { requires S::kOutOfLine; };

template <BatchShader S>
[[gnu::noinline]] void fragment_batch_out_of_line(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& varyings,
                                                  const simd::f8& z, bool front_facing, std::array<simd::f8, 4>& rgba) {
    simd::on_best_path([&]<bool>() { shader.fragment_batch(varyings, z, front_facing, rgba); });
}
template <QuadRowShader S>
[[gnu::noinline]] void fragment_quad_rows_out_of_line(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v0,
                                                      const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v1, const simd::f8& z0,
                                                      const simd::f8& z1, bool front_facing, std::array<simd::f8, 4>& rgba0,
                                                      std::array<simd::f8, 4>& rgba1) {
    simd::on_best_path([&]<bool>() { shader.fragment_quad_rows(v0, v1, z0, z1, front_facing, rgba0, rgba1); });
}
template <QuadBlockShader S>
[[gnu::noinline]] void fragment_quad_block_out_of_line(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>> (&v)[4],
                                                       const simd::f8 (&z)[4], bool front_facing, std::array<simd::f8, 4> (&rgba)[4]) {
    simd::on_best_path([&]<bool>() { shader.fragment_quad_block(v, z, front_facing, rgba); });
}
template <Shader S>
[[gnu::noinline]] bool fragment_out_of_line(const S& shader, const typename S::Varyings& v, const FragCoord& frag, glm::vec4& color) {
    return simd::on_best_path([&]<bool>() { return shader.fragment(v, frag, color); });
}

// The shader's fragment_batch and fragment as the back ends call them.
template <BatchShader S>
inline void run_fragment_batch(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& varyings,
                               const simd::f8& z, bool front_facing, std::array<simd::f8, 4>& rgba) {
    if constexpr (OutOfLineShader<S>) fragment_batch_out_of_line(shader, varyings, z, front_facing, rgba);
    else shader.fragment_batch(varyings, z, front_facing, rgba);
}
template <QuadRowShader S>
inline void run_fragment_quad_rows(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v0,
                                   const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v1, const simd::f8& z0, const simd::f8& z1,
                                   bool front_facing, std::array<simd::f8, 4>& rgba0, std::array<simd::f8, 4>& rgba1) {
    if constexpr (OutOfLineShader<S>) fragment_quad_rows_out_of_line(shader, v0, v1, z0, z1, front_facing, rgba0, rgba1);
    else shader.fragment_quad_rows(v0, v1, z0, z1, front_facing, rgba0, rgba1);
}
template <QuadBlockShader S>
inline void run_fragment_quad_block(const S& shader, const std::array<simd::f8, kVaryingCount<typename S::Varyings>> (&v)[4],
                                    const simd::f8 (&z)[4], bool front_facing, std::array<simd::f8, 4> (&rgba)[4]) {
    if constexpr (OutOfLineShader<S>) fragment_quad_block_out_of_line(shader, v, z, front_facing, rgba);
    else shader.fragment_quad_block(v, z, front_facing, rgba);
}
template <Shader S>
inline bool run_fragment(const S& shader, const typename S::Varyings& v, const FragCoord& frag, glm::vec4& color) {
    if constexpr (OutOfLineShader<S>) return fragment_out_of_line(shader, v, frag, color);
    else return shader.fragment(v, frag, color);
}

// One fragment of pixel (x, y) whose samples `covered` lie at depths z: the depth test
// (depth_stencil.h), the shader with the varyings make_varyings() returns, then the depth
// write and the output merge for the samples that passed, unless the shader discarded.
template <int Samples, bool Blended, class DepthStencil, Shader S, class MakeVaryings>
inline void shade_fragment(const S& shader, const DepthStencil& depth, const BlendSettings& blend, Framebuffer& fb, int x, int y,
                           unsigned covered, const float* z, float center_z, bool front_facing,
                           MakeVaryings&& make_varyings, uint64_t& shaded) {
    const size_t base = fb.sample_index(x, y);
    const unsigned pass = depth.template test_pixel<Samples>(fb.depth_data() + base, covered, z);
    if (!pass) return;
    ++shaded;
    const typename S::Varyings v = make_varyings();
    const FragCoord frag{float(x) + 0.5f, float(y) + 0.5f, center_z, front_facing};
    glm::vec4 color;
    if (!run_fragment(shader, v, frag, color)) return;
    depth.template write_pixel<Samples>(fb.depth_data() + base, pass, z);
    if (blend.color_mask) merge_fragment<Samples, Blended>(blend, fb.color_data() + base, pass, color);
}

// Eight pixels [x, x + 8) of a row whose lanes `pass` passed the depth test: the batch
// shader, then the output merge of those lanes.
template <bool Blended, BatchShader S>
inline void shade_group(const S& shader, const BlendSettings& blend, Rgba8* row, int x, int width, simd::i8 pass,
                        const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& varyings, simd::f8 z,
                        bool front_facing) {
    std::array<simd::f8, 4> rgba;
    run_fragment_batch(shader, varyings, z, front_facing, rgba);
    blend_group<Blended>(blend, row, x, width, pass, rgba);
}

}  // namespace softraster
