// Stage 1, vertex processing: run the vertex shader once per vertex of the buffer.
//
// The results form the post-transform vertex buffer that primitive assembly indexes into,
// so a vertex shared by many triangles is shaded once. Everything else that depends on one
// vertex only is done here too, once: its clip outcode, the perspective divide and viewport
// mapping, and the snapping of its window position to 24.8 fixed point.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/shader.h"
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

// Shades vertices [begin, end) of `vertices` into out[begin, end).
template <Shader S>
void process_vertices(const S& shader, std::span<const typename S::Vertex> vertices, size_t begin, size_t end,
                      const ClipPlanes& planes, const Viewport& vp,
                      std::span<ShadedVertex<kVaryingCount<typename S::Varyings>>> out) {
    for (size_t i = begin; i < end; ++i) {
        typename S::Varyings v{};
        auto& o = out[i];
        o.clip.position = shader.vertex(vertices[i], v);
        o.clip.var = to_array(v);
        const glm::vec4 p = o.clip.position;
        o.finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        if (!o.finite) continue;
        o.outcode = planes.outcode(p);
        if (o.outcode == 0 && !finish_vertex(o.clip, vp, o)) o.finite = false;
    }
}

}  // namespace softraster
