// Stage 1, vertex processing: run the vertex shader once per vertex of the buffer.
//
// The results form the post-transform vertex buffer that primitive assembly indexes into,
// so a vertex shared by many triangles is shaded once. Everything else that depends on one
// vertex only is done here too, once: its clip outcode, the perspective divide and viewport
// mapping, and the snapping of its window position to 24.8 fixed point.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include <glm/vec4.hpp>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

// A vertex after the vertex shader: clip position and varyings, and (when outcode == 0)
// its window position. Window data of a vertex outside the clip volume is not used: the
// triangles that touch it go through the clipper.
// Ordered by who reads it: binning reads the first 16 bytes, setup the window position and
// the varyings, the clipper the clip vertex. The varyings are stored once (setup reads them
// from `clip`): a million-triangle mesh has this buffer written and read twice per frame,
// far larger than the caches, so every byte of it is memory traffic.
template <int N>
struct ShadedVertex {
    int32_t X = 0, Y = 0;   // window position in 24.8 fixed point (snapped)
    unsigned outcode = 0;   // planes of ClipPlanes::for_viewport it is outside of
    bool finite = true;     // all clip coordinates finite
    WindowPosition window;  // valid when outcode == 0
    ClipVertex<N> clip;
};

// Maps a clipped (or inside) vertex to window space and snaps it. False if it cannot be
// mapped (w <= 0 or non-finite results: degenerate user matrices).
template <int N>
bool finish_vertex(const ClipVertex<N>& c, const Viewport& vp, ShadedVertex<N>& out) {
    out.clip = c;
    out.outcode = 0;
    if (!to_window(c.position, vp, out.window)) return false;
    out.X = int32_t(snap_to_subpixel(out.window.x));
    out.Y = int32_t(snap_to_subpixel(out.window.y));
    return true;
}

// The fixed-function part of vertex processing for eight shaded vertices at once (their
// clip positions set): finiteness, clip outcode, perspective divide and viewport mapping,
// each lane computed by the helpers ClipPlanes::outcode and to_window use (dot4,
// window_coordinates), so the results are the same bits as one vertex at a time (no
// contraction: CMakeLists.txt).
template <int N>
void finish_vertices8(ShadedVertex<N>* out, const ClipPlanes& planes, const Viewport& vp) {
    using namespace simd;
    f8 x, y, z, w;
    for (int l = 0; l < kLanes; ++l) {
        const glm::vec4& p = out[l].clip.position;
        x[l] = p.x, y[l] = p.y, z[l] = p.z, w[l] = p.w;
    }
    // |v| <= FLT_MAX: false for infinities and NaN, as !std::isfinite
    auto finite = [](f8 v) { return select(v < 0.0f, -v, v) <= std::numeric_limits<float>::max(); };
    const i8 in_range = finite(x) & finite(y) & finite(z) & finite(w);
    i8 outcode{};
    for (size_t i = 0; i < size_t(ClipPlanes::kCount); ++i) {
        const glm::vec4& q = planes.planes[i];
        const f8 d = dot4(q.x, q.y, q.z, q.w, x, y, z, w);
        outcode |= (d < 0.0f) & int32_t(1u << i);
    }
    const auto [wx, wy, wz, inv_w] = window_coordinates(x, y, z, w, vp);
    const i8 mapped = (w > 0.0f) & finite(wx) & finite(wy) & finite(wz) & finite(inv_w);
    for (int l = 0; l < kLanes; ++l) {
        ShadedVertex<N>& o = out[l];
        o.finite = in_range[l] != 0;
        o.outcode = unsigned(outcode[l]);
        if (!o.finite || o.outcode != 0) continue;
        if (!mapped[l]) {
            o.finite = false;
            continue;
        }
        o.window = {wx[l], wy[l], wz[l], inv_w[l]};
        o.X = int32_t(snap_to_subpixel(wx[l]));
        o.Y = int32_t(snap_to_subpixel(wy[l]));
    }
}

// The same out of line, in each CPU path's copy (simd.h): it depends on the varying count
// alone, so it is compiled once per count (src/scene/surface_phases.cpp), not again with
// every shader; a call per eight vertices costs nothing that shows.
template <int N>
[[gnu::noinline]] SOFTRASTER_AVX2_TARGET void finish_vertices8_wide(ShadedVertex<N>* out, const ClipPlanes& planes, const Viewport& vp) {
    finish_vertices8(out, planes, vp);
}
template <int N>
[[gnu::noinline]] void finish_vertices8_generic(ShadedVertex<N>* out, const ClipPlanes& planes, const Viewport& vp) {
    finish_vertices8(out, planes, vp);
}

// Shades vertices [begin, end) of `vertices` into out[begin, end): the vertex shader one
// vertex at a time, the fixed-function part eight at a time. WideLanes: in the AVX2 copy.
template <bool WideLanes = false, Shader S>
void process_vertices(const S& shader, std::span<const typename S::Vertex> vertices, size_t begin, size_t end,
                      const ClipPlanes& planes, const Viewport& vp,
                      std::span<ShadedVertex<kVaryingCount<typename S::Varyings>>> out) {
    auto shade = [&](size_t i) {
        typename S::Varyings v{};
        out[i].clip.position = shader.vertex(vertices[i], v);
        out[i].clip.var = to_array(v);
    };
    size_t i = begin;
    for (; i + simd::kLanes <= end; i += simd::kLanes) {
        for (size_t l = 0; l < size_t(simd::kLanes); ++l) shade(i + l);
        if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) finish_vertices8_wide(&out[i], planes, vp);
        else finish_vertices8_generic(&out[i], planes, vp);
    }
    for (; i < end; ++i) {  // the last few
        shade(i);
        auto& o = out[i];
        const glm::vec4 p = o.clip.position;
        o.finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        o.outcode = o.finite ? planes.outcode(p) : 0;
        if (o.outcode == 0 && o.finite && !finish_vertex(o.clip, vp, o)) o.finite = false;
    }
}

}  // namespace softraster
