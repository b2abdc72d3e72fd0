// Stage 2, primitive assembly: group post-transform vertices into triangles, lines, points.
//
// Index buffers are checked once, up front (validate_indices). A primitive with a
// non-finite clip coordinate (a NaN or infinite input position) is dropped here, before it
// can poison clipping or setup; one wholly outside a clip plane too. One that crosses a
// plane goes through the clipper (clipping.h), whose new vertices are mapped to window
// space (viewport.h) and kept beside the post-transform buffer: a triangle's corner is an
// index into one or the other.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include <glm/vec4.hpp>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/vertex_processing.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

inline int vertices_per_primitive(Topology t) {
    return t == Topology::Triangles ? 3 : t == Topology::Lines ? 2 : 1;
}

inline void validate_indices(std::span<const uint32_t> indices, size_t vertex_count, Topology t) {
    if (indices.size() % size_t(vertices_per_primitive(t)) != 0)
        throw std::invalid_argument("index count is not a multiple of the primitive size");
    if (vertex_count > UINT32_MAX) return;  // (every index is in range)
    // A flag per index, ORed, then one test: a loop that vectorizes to a compare and an OR per
    // vector (an unsigned maximum has no SSE2 instruction, and took three times as long).
    const auto count = uint32_t(vertex_count);
    uint32_t past_end = 0;
    for (uint32_t i : indices) past_end |= uint32_t(i >= count);
    if (past_end) throw std::out_of_range("index past the end of the vertex buffer");
}

// A corner flagged with kClippedVertex indexes the clipper's output, otherwise the
// post-transform buffer.
inline constexpr uint32_t kClippedVertex = 0x80000000u;

// A triangle as primitive assembly passes it on and binning keeps it: its three corners
// (corner_vertex).
struct TriangleRef {
    uint32_t v[3];
};

template <int N>
const ShadedVertex<N>& corner_vertex(uint32_t i, const ShadedVertex<N>* post, const std::vector<ShadedVertex<N>>& clipped) {
    return (i & kClippedVertex) ? clipped[i & ~kClippedVertex] : post[i];
}

// A shader's flat varyings (shader.h, kFlatVaryings: bit k for float k) and which vertex of
// a primitive provides them, the first or (OpenGL's default) the last.
struct FlatVaryings {
    uint64_t mask = 0;
    bool first = false;
};

// Assembles triangle (ia, ib, ic) (its corners' two parts in post and clip) and calls
// emit(ref, a, b, c) if it may be visible, with its corners as indices (`ref`,
// corner_vertex) and as vertices with snapped window positions (X, Y): as it is when it lies
// inside every plane (their ClipInfo), else as the fan (0, k, k+1) of its clipped polygon,
// whose vertices are appended to `clipped` (ShadedVertex). The clipper runs against
// `planes` (near, far, guard band) in `poly`, the caller's. Every vertex of a clipped
// polygon carries the flat varyings of the triangle's provoking vertex, so each triangle of
// its fan has them whichever corner provokes.
template <int N, class Emit>
inline void assemble_triangle(uint32_t ia, uint32_t ib, uint32_t ic, const ShadedVertex<N>* post, const ClipInfo* clip, const ClipPlanes& planes,
                              const Viewport& vp, FlatVaryings flat, std::vector<ShadedVertex<N>>& clipped, ClipPolygon<N>& poly, Emit&& emit) {
    const ClipInfo &ca = clip[ia], &cb = clip[ib], &cc = clip[ic];
    if (!ca.finite || !cb.finite || !cc.finite) return;  // NaN or infinite position
    if (ca.outcode & cb.outcode & cc.outcode) return;     // all outside one plane
    const unsigned mask = ca.outcode | cb.outcode | cc.outcode;
    if (mask == 0) return emit(TriangleRef{{ia, ib, ic}}, ca, cb, cc);
    const ShadedVertex<N>&a = post[ia], &b = post[ib], &c = post[ic];
    const int n = clip_triangle(clip_vertex(ca, a), clip_vertex(cb, b), clip_vertex(cc, c), planes, mask, poly);
    const auto first = uint32_t(clipped.size());
    for (int k = 0; k < n; ++k) {
        ShadedVertex<N> v;
        if (!finish_vertex(poly.v[size_t(k)], vp, v)) {  // a degenerate user matrix: the triangle is dropped
            clipped.resize(first);
            return;
        }
        const ShadedVertex<N>& provoking = flat.first ? a : c;
        for (size_t j = 0; j < size_t(N); ++j)
            if ((flat.mask >> j) & 1) v.var[j] = provoking.var[j];
        clipped.push_back(v);
    }
    for (uint32_t k = 1; k + 1 < uint32_t(n); ++k)
        emit(TriangleRef{{first | kClippedVertex, (first + k) | kClippedVertex, (first + k + 1) | kClippedVertex}}, clipped[first],
             clipped[first + k], clipped[first + k + 1]);
}

// Assembles the triangles of `indices` (three per triangle) in order (assemble_triangle).
template <int N, class Emit>
void assemble_triangles(std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipInfo* clip, const ClipPlanes& planes,
                        const Viewport& vp, FlatVaryings flat, std::vector<ShadedVertex<N>>& clipped, Emit&& emit) {
    ClipPolygon<N> poly;
    // A triangle's corners sit anywhere in the vertex buffer, and their loads wait behind the
    // last triangle's branches: fetch two corners of the triangle eight places ahead into the
    // cache (the other is mostly one a recent triangle read): their clip parts, all that
    // binning reads unless the triangle is clipped.
    constexpr size_t kAhead = 3 * 8;
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        if (i + kAhead + 2 < indices.size()) __builtin_prefetch(clip + indices[i + kAhead + 1]), __builtin_prefetch(clip + indices[i + kAhead + 2]);
        assemble_triangle(indices[i], indices[i + 1], indices[i + 2], post, clip, planes, vp, flat, clipped, poly, emit);
    }
}

// Assembles lines (two indices each) or points (one each), clips them and appends their
// window vertices to `out`, two per line, one per point. Lines are clipped (Liang–Barsky)
// against `planes`, whose sides lie out at the guard band, as triangles are: a line that
// leaves the picture keeps its true end, so the pixels at the picture's border are the
// ones the whole line covers (as llvmpipe). A point is kept when inside the view volume.
template <int N>
void assemble_lines_points(Topology topology, std::span<const uint32_t> indices, const ShadedVertex<N>* post,
                           const ClipInfo* clip, const ClipPlanes& planes, const Viewport& vp, std::vector<WindowVertex<N>>& out) {
    const ClipPlanes frustum = ClipPlanes::frustum();
    const size_t per = topology == Topology::Lines ? 2 : 1;
    for (size_t i = 0; i + per <= indices.size(); i += per) {
        const uint32_t first = indices[i], last = indices[i + per - 1];
        if (!clip[first].finite || !clip[last].finite) continue;
        ClipVertex<N> a = clip_vertex(clip[first], post[first]), b = clip_vertex(clip[last], post[last]);
        if (per == 2 ? !clip_line(a, b, planes) : frustum.outcode(a.position) != 0) continue;
        WindowVertex<N> wa, wb;
        if (!to_window(a, vp, wa) || !to_window(b, vp, wb)) continue;
        out.push_back(wa);
        if (per == 2) out.push_back(wb);
    }
}

}  // namespace softraster
