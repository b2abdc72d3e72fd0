// Stage 1, vertex processing: run the vertex shader once per vertex of the buffer.
//
// The results form the post-transform vertex buffer that primitive assembly indexes into,
// so a vertex shared by many triangles is shaded once. Everything else that depends on one
// vertex only is done here too, once: its clip outcode, the perspective divide and viewport
// mapping, and the snapping of its window position to 24.8 fixed point.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include <glm/vec4.hpp>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd.h"
#include "softraster/pipeline/simd_avx2.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

// A vertex after the vertex shader, in two parts kept in two arrays, by who reads them.
// ClipInfo: what the front end reads, right after vertex processing made it: primitive
// assembly its flags, binning its snapped window position, the clipper its clip position.
struct ClipInfo {
    glm::vec4 position;    // homogeneous clip coordinates
    int32_t X = 0, Y = 0;  // window position in 24.8 fixed point (snapped), valid when outcode == 0
    unsigned outcode = 0;  // planes of ClipPlanes::for_viewport it is outside of
    bool finite = true;    // all clip coordinates finite
};
// ShadedVertex: what the back end's setup reads, long after vertex processing wrote it: its
// snapped and window positions (valid when the outcode is 0: the triangles that touch a
// vertex outside the clip volume go through the clipper) and its varyings. A million-triangle
// mesh, or twenty thousand small objects, have this buffer far larger than the caches, so
// every byte of it is memory traffic: with the clip part in it, a vertex of six varyings
// took 72 bytes, not 48 (docs/performance.md).
template <int N>
struct ShadedVertex {
    int32_t X = 0, Y = 0;      // window position in 24.8 fixed point (snapped)
    WindowPosition window;     // window position, depth and 1/w
    std::array<float, N> var;  // varyings
};

// The clipper's view of a vertex: its clip position with its varyings.
template <int N>
ClipVertex<N> clip_vertex(const ClipInfo& c, const ShadedVertex<N>& v) {
    return {c.position, v.var};
}

// Maps clip position p to window space and snaps it, into out's positions (its varyings
// untouched). False if it cannot be mapped (w <= 0 or non-finite results: degenerate user
// matrices).
template <int N>
bool map_to_window(const glm::vec4& p, const Viewport& vp, ShadedVertex<N>& out) {
    if (!to_window(p, vp, out.window)) return false;
    out.X = int32_t(snap_to_subpixel(out.window.x));
    out.Y = int32_t(snap_to_subpixel(out.window.y));
    return true;
}
// The same for a clipped (or inside) vertex, with its varyings.
template <int N>
bool finish_vertex(const ClipVertex<N>& c, const Viewport& vp, ShadedVertex<N>& out) {
    out.var = c.var;
    return map_to_window(c.position, vp, out);
}

// The fixed-function part of vertex processing for eight vertices, their clip positions
// x, y, z, w as lanes: finiteness, clip outcode, perspective divide and viewport mapping,
// each lane computed by the helpers ClipPlanes::outcode and to_window use (distances,
// window_coordinates), so the results are the same bits as one vertex at a time (no
// contraction: CMakeLists.txt).
struct Finished8 {
    simd::i8 finite;   // ClipInfo::finite: all clip coordinates finite, and, inside, mapped
    simd::i8 outcode;  // ClipInfo::outcode
    simd::i8 valid;    // finite and inside: the window position is valid
    simd::f8 wx, wy, wz, inv_w;
};
// (Vectors by reference: see lanes::gather in texture_lanes.h.)
inline void finish8(const simd::f8& x, const simd::f8& y, const simd::f8& z, const simd::f8& w, const ClipPlanes& planes, const Viewport& vp,
                    Finished8& out) {
    using namespace simd;
    // |v| <= FLT_MAX: false for infinities and NaN, as !std::isfinite
    auto finite = [](f8 v) { return select(v < 0.0f, -v, v) <= std::numeric_limits<float>::max(); };
    const i8 in_range = finite(x) & finite(y) & finite(z) & finite(w);
    const std::array<f8, ClipPlanes::kCount> d = planes.distances(x, y, z, w);
    i8 outcode{};
    for (size_t i = 0; i < size_t(ClipPlanes::kCount); ++i) outcode |= (d[i] < 0.0f) & int32_t(1u << i);
    const auto [wx, wy, wz, inv_w] = window_coordinates(x, y, z, w, vp);
    const i8 mapped = (w > 0.0f) & finite(wx) & finite(wy) & finite(wz) & finite(inv_w);
    // (A vertex outside is finite whether or not it maps; one inside that cannot be mapped is not.)
    const i8 finite_out = in_range & ((outcode != 0) | mapped);
    out = {finite_out, outcode, finite_out & (outcode == 0), wx, wy, wz, inv_w};
}

// Eight vertices at once (their clip positions set), lane by lane into their two parts.
template <int N>
void finish_vertices8(ShadedVertex<N>* out, ClipInfo* clip, const ClipPlanes& planes, const Viewport& vp) {
    using namespace simd;
    f8 x, y, z, w;
    for (int l = 0; l < kLanes; ++l) {
        const glm::vec4& p = clip[l].position;
        x[l] = p.x, y[l] = p.y, z[l] = p.z, w[l] = p.w;
    }
    Finished8 f;
    finish8(x, y, z, w, planes, vp, f);
    for (int l = 0; l < kLanes; ++l) {
        ShadedVertex<N>& o = out[l];
        ClipInfo& c = clip[l];
        c.finite = f.finite[l] != 0;
        c.outcode = unsigned(f.outcode[l]);
        if (!f.valid[l]) continue;
        o.window = {f.wx[l], f.wy[l], f.wz[l], f.inv_w[l]};
        o.X = c.X = int32_t(snap_to_subpixel(f.wx[l]));
        o.Y = c.Y = int32_t(snap_to_subpixel(f.wy[l]));
    }
}
#if SOFTRASTER_HAS_AVX2_PATH
// The same with the clip positions read as eight 16-byte rows and the results written as
// rows, each set of four turned from rows to lanes and back (simd::load_columns,
// store_columns, transpose4x4_halves),
// with no branch per vertex: the window coordinates and snapped positions of the vertices
// that are not valid are written too, which their readers never look at ("valid when the
// outcode is 0").
// Snapping: v 256 is exact in float, and cvtps2dq rounds it to nearest even as lrint does.
template <int N>
[[gnu::target("avx2")]] inline void finish_vertices8_avx2(ShadedVertex<N>* out, ClipInfo* clip, const ClipPlanes& planes, const Viewport& vp) {
    static_assert(offsetof(ClipInfo, X) == 16 && offsetof(ClipInfo, outcode) == 24 && offsetof(ClipInfo, finite) == 28 && sizeof(ClipInfo) == 32);
    static_assert(offsetof(ShadedVertex<N>, window) == 8 && sizeof(WindowPosition) == 16);
    simd::f8 p[4];  // x, y, z, w
    simd::load_columns(&clip->position, sizeof(ClipInfo), p);
    Finished8 f;
    finish8(p[0], p[1], p[2], p[3], planes, vp, f);
    const __m256 sub = _mm256_set1_ps(float(kSubpixelOne));
    const __m256i valid = __m256i(f.valid);
    const __m256i X = _mm256_and_si256(_mm256_cvtps_epi32(_mm256_mul_ps(__m256(f.wx), sub)), valid);
    const __m256i Y = _mm256_and_si256(_mm256_cvtps_epi32(_mm256_mul_ps(__m256(f.wy), sub)), valid);
    const simd::f8 window[4] = {f.wx, f.wy, f.wz, f.inv_w};
    simd::store_columns(window, 4, &out->window, sizeof(ShadedVertex<N>));
    // The snapped position and flags go to two places, so their rows are made once here.
    __m256i tail[4] = {X, Y, __m256i(f.outcode), _mm256_and_si256(__m256i(f.finite), _mm256_set1_epi32(1))};  // (finite: a bool, then padding)
    simd::transpose4x4_halves(tail);
    for (int k = 0; k < 4; ++k)  // vertices k (low halves) and k + 4 (high halves)
        for (int h = 0; h < 2; ++h) {
            const int l = k + 4 * h;
            const __m128i t = h ? _mm256_extracti128_si256(tail[k], 1) : _mm256_castsi256_si128(tail[k]);
            _mm_storeu_si128(reinterpret_cast<__m128i*>(&clip[l].X), t);
            _mm_storel_epi64(reinterpret_cast<__m128i*>(&out[l].X), t);
        }
}
#endif

// The same out of line, in each CPU path's copy (simd.h): it depends on the varying count
// alone, so it is compiled once per count (src/scene/surface_phases.cpp), not again with
// every shader; a call per eight vertices costs nothing that shows.
template <int N>
[[gnu::noinline]] SOFTRASTER_AVX2_TARGET void finish_vertices8_wide(ShadedVertex<N>* out, ClipInfo* clip, const ClipPlanes& planes, const Viewport& vp) {
#if SOFTRASTER_HAS_AVX2_PATH
    finish_vertices8_avx2(out, clip, planes, vp);
#else
    finish_vertices8(out, clip, planes, vp);
#endif
}
template <int N>
[[gnu::noinline]] void finish_vertices8_generic(ShadedVertex<N>* out, ClipInfo* clip, const ClipPlanes& planes, const Viewport& vp) {
    finish_vertices8(out, clip, planes, vp);
}

#if SOFTRASTER_HAS_AVX2_PATH
// A lane shader's eight vertices in[0..8) into out[0..8) (varyings) and clip[0..8) (clip
// positions), the lanes turned into records four floats at a time.
template <LaneVertexShader S>
SOFTRASTER_AVX2_TARGET void shade_vertices8(const S& shader, const typename S::Vertex* in, ShadedVertex<kVaryingCount<typename S::Varyings>>* out,
                                            ClipInfo* clip) {
    constexpr size_t N = size_t(kVaryingCount<typename S::Varyings>);
    std::array<simd::f8, N> var;
    std::array<simd::f8, 4> position;
    shader.vertex_lanes(in, var, position);
    for (size_t g = 0; g < N; g += 4) simd::store_columns(&var[g], int(std::min<size_t>(4, N - g)), &out->var[g], sizeof(*out));
    simd::store_columns(position.data(), 4, &clip->position, sizeof(*clip));
}
#endif

// Shades vertices [begin, end) of `vertices` into out[begin, end) and clip[begin, end): the
// vertex shader one vertex at a time (or eight, for a lane shader in the AVX2 copy), the
// fixed-function part eight at a time. WideLanes: in the AVX2 copy.
template <bool WideLanes = false, Shader S>
void process_vertices(const S& shader, std::span<const typename S::Vertex> vertices, size_t begin, size_t end,
                      const ClipPlanes& planes, const Viewport& vp,
                      std::span<ShadedVertex<kVaryingCount<typename S::Varyings>>> out, std::span<ClipInfo> clip) {
    auto shade = [&](size_t i) {
        typename S::Varyings v{};
        clip[i].position = shader.vertex(vertices[i], v);
        out[i].var = to_array(v);
    };
    size_t i = begin;
    for (; i + simd::kLanes <= end; i += simd::kLanes) {
#if SOFTRASTER_HAS_AVX2_PATH
        if constexpr (WideLanes && LaneVertexShader<S>) shade_vertices8(shader, &vertices[i], &out[i], &clip[i]);
        else
#endif
            for (size_t l = 0; l < size_t(simd::kLanes); ++l) shade(i + l);
        if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) finish_vertices8_wide(&out[i], &clip[i], planes, vp);
        else finish_vertices8_generic(&out[i], &clip[i], planes, vp);
    }
    for (; i < end; ++i) {  // the last few
        shade(i);
        ClipInfo& c = clip[i];
        const glm::vec4 p = c.position;
        c.finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        c.outcode = c.finite ? planes.outcode(p) : 0;
        if (c.outcode != 0 || !c.finite) continue;
        if (!map_to_window(p, vp, out[i])) c.finite = false;
        c.X = out[i].X, c.Y = out[i].Y;
    }
}

}  // namespace softraster
