// Lines and points become quads: after clipping and the viewport mapping, each line or
// point is turned into a quadrilateral in window space, two triangles that then go through
// binning, setup, rasterization and the rest exactly like any triangle. This is how Mesa's
// llvmpipe draws them (lp_setup_line.c, lp_setup_point.c); it gives lines and points the
// triangles' fill rule, sample positions and both back ends for free.
//
// Lines, one sample per pixel (OpenGL 4.6, 14.5.1, "diamond exit"). Take the major axis u
// (x when |dx| >= |dy|, else y) and the minor axis v. The line covers, in each column (a
// row, when y is major) it crosses, the pixels whose centers lie within width/2 of the line
// across the minor axis: a parallelogram whose long sides are the line moved by +-width/2
// along v, so every column gets `width` pixels (width rounded to a whole number, at least
// 1). Which columns: those whose centers lie between the endpoints, except that the
// endpoints' own columns follow the diamond-exit rule. Let the diamond of a pixel be the
// open square |x - cx| + |y - cy| < 1/2 around its center; the column of the first endpoint
// a is drawn when the segment crosses the diamond of the pixel holding a, the column of the
// last endpoint b when the segment crosses the diamond of the pixel holding b and b is not
// inside it. So a strip of lines draws each shared endpoint once.
//
// Lines with multisampling are rectangles: the segment widened by width/2 on each side,
// square ends, covering the samples inside it (OpenGL 4.6, 14.5.3).
//
// Points are squares of side `size` (at least one pixel) centered on the vertex, covering
// the pixel centers (or samples) inside, as OpenGL's point sprites (14.4).
//
// Varyings: a point's are its vertex's, constant. Along a line they change with the
// position along the major axis only (across a multisampled line's width they do not change
// either: the rectangle's corners carry their endpoint's values), perspective-correct like a
// triangle's. Depth is linear in window space along the same parameter. Lines and points
// always face front, and polygon offset does not apply to them (as in OpenGL).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/primitive_assembly.h"

namespace softraster {

// The rasterization settings of a draw of lines or points.
struct LinePointShape {
    float line_width = 1.0f;
    float point_size = 1.0f;
    bool multisampled = false;  // lines are rectangles
    FrontFace front = FrontFace::CCW;
};

// Whether the segment from a to b (window coordinates) meets the open diamond of the pixel
// centered at (cx, cy). Liang–Barsky (as clipping.h): the diamond is four half-planes
// s1 (x - cx) + s2 (y - cy) < 1/2; each bounds the segment's parameter t from one side.
inline bool segment_meets_diamond(float ax, float ay, float bx, float by, float cx, float cy) {
    double lo = 0.0, hi = 1.0;
    for (const double s1 : {-1.0, 1.0})
        for (const double s2 : {-1.0, 1.0}) {
            const double p = s1 * (double(bx) - ax) + s2 * (double(by) - ay);  // the side's slope in t
            const double q = 0.5 - (s1 * (double(ax) - cx) + s2 * (double(ay) - cy));
            if (p == 0.0) {
                if (q <= 0.0) return false;
            } else if (p > 0.0) {
                hi = std::min(hi, q / p);
            } else {
                lo = std::max(lo, q / p);
            }
        }
    return lo < hi;
}

inline bool inside_diamond(float x, float y, float cx, float cy) {
    return std::fabs(double(x) - cx) + std::fabs(double(y) - cy) < 0.5;
}

// A window-space vertex of a quad: a point at parameter t of the way from a to b, moved by
// (ox, oy) pixels (kept exact in fixed point: offsets are multiples of 1/256).
template <int N>
ShadedVertex<N> quad_corner(const WindowVertex<N>& a, const WindowVertex<N>& b, double t, float x, float y, int32_t ox,
                            int32_t oy, uint64_t flat, const WindowVertex<N>& provoking) {
    ShadedVertex<N> c;
    c.X = int32_t(snap_to_subpixel(x)) + ox;
    c.Y = int32_t(snap_to_subpixel(y)) + oy;
    const double qa = a.inv_w, qb = b.inv_w, q = qa + t * (qb - qa);  // 1/w is linear in window space
    c.window = {x + float(ox) / float(kSubpixelOne), y + float(oy) / float(kSubpixelOne),
                float(double(a.z) + t * (double(b.z) - a.z)), float(q)};
    for (size_t k = 0; k < size_t(N); ++k)  // var/w is linear too: var = (var/w) / (1/w)
        c.var[k] = (flat >> k) & 1 ? provoking.var[k]
                                   : float((double(a.var[k]) * qa + t * (double(b.var[k]) * qb - double(a.var[k]) * qa)) / q);
    return c;
}

// Calls emit(c0, c1, c2, c3), the corners of the quad in order around it, for the line a -> b.
template <int N, class Emit>
void line_quad(const WindowVertex<N>& a, const WindowVertex<N>& b, const LinePointShape& shape, uint64_t flat,
               const WindowVertex<N>& provoking, Emit&& emit) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0.0f && dy == 0.0f) return;
    auto corner = [&](double t, float x, float y, int32_t ox, int32_t oy) { return quad_corner(a, b, t, x, y, ox, oy, flat, provoking); };
    if (shape.multisampled) {
        const float scale = shape.line_width * 0.5f / std::sqrt(dx * dx + dy * dy);
        const auto tx = int32_t(snap_to_subpixel(-dy * scale)), ty = int32_t(snap_to_subpixel(dx * scale));
        emit(corner(0, a.x, a.y, -tx, -ty), corner(1, b.x, b.y, -tx, -ty), corner(1, b.x, b.y, tx, ty), corner(0, a.x, a.y, tx, ty));
        return;
    }
    const bool x_major = std::fabs(dx) >= std::fabs(dy);
    // In (u, v) = (major, minor) coordinates.
    const float au = x_major ? a.x : a.y, av = x_major ? a.y : a.x, bu = x_major ? b.x : b.y, bv = x_major ? b.y : b.x;
    const float du = bu - au, slope = (bv - av) / du;
    const bool forward = du > 0.0f;
    // The endpoints' columns: whether the diamond-exit rule draws them. In a column the line
    // meets one diamond, if any: that of the pixel its band covers at the column's center
    // (the pixel whose center lies within 1/2 of the line there).
    auto pixel_center_in_column = [&](float u) {
        const float cu = std::floor(u) + 0.5f, v = av + (cu - au) * slope;
        const float cv = std::ceil(v - 1.0f) + 0.5f;  // the center in [v - 1/2, v + 1/2)
        return x_major ? std::array<float, 2>{cu, cv} : std::array<float, 2>{cv, cu};
    };
    const auto [acx, acy] = pixel_center_in_column(au);
    const auto [bcx, bcy] = pixel_center_in_column(bu);
    const bool draw_first = segment_meets_diamond(a.x, a.y, b.x, b.y, acx, acy);
    const bool draw_last = !inside_diamond(b.x, b.y, bcx, bcy) && segment_meets_diamond(a.x, a.y, b.x, b.y, bcx, bcy);
    // Whether the parallelogram between the endpoints themselves holds each endpoint column's
    // center (the fill rule: a column center on its left edge is in, on its right edge out);
    // where it differs from the rule, that end moves along the line to the column's border.
    const float a_center = std::floor(au) + 0.5f, b_center = std::floor(bu) + 0.5f;
    const bool holds_first = forward ? au <= a_center : a_center < au;
    const bool holds_last = forward ? b_center < bu : bu <= b_center;
    float us = au, ue = bu;
    if (holds_first != draw_first) us = std::floor(au) + (forward != draw_first ? 1.0f : 0.0f);
    if (holds_last != draw_last) ue = std::floor(bu) + (forward == draw_last ? 1.0f : 0.0f);
    if (forward ? !(us < ue) : !(ue < us)) return;  // no column left
    const float vs = av + (us - au) * slope, ve = av + (ue - au) * slope;
    const auto half = int32_t(std::max(1L, std::lround(shape.line_width)) * kSubpixelOne / 2);
    auto at = [&](float u, float v, double t, int32_t side) {
        return x_major ? corner(t, u, v, 0, side) : corner(t, v, u, side, 0);
    };
    const double ts = double(us - au) / du, te = double(ue - au) / du;
    emit(at(us, vs, ts, -half), at(ue, ve, te, -half), at(ue, ve, te, half), at(us, vs, ts, half));
}

// The quad of a point: a square of side point_size (at least one pixel) around it.
template <int N, class Emit>
void point_quad(const WindowVertex<N>& p, const LinePointShape& shape, Emit&& emit) {
    const int32_t side = std::max(int32_t(kSubpixelOne), int32_t(snap_to_subpixel(shape.point_size)));
    const int32_t lo = -side / 2, hi = lo + side;
    auto corner = [&](int32_t ox, int32_t oy) { return quad_corner(p, p, 0.0, p.x, p.y, ox, oy, 0, p); };
    emit(corner(lo, lo), corner(hi, lo), corner(hi, hi), corner(lo, hi));
}

// The front end for one chunk of a draw of lines or points: assembly and clipping
// (primitive_assembly.h), the quads, then binning (binning.h) of their two triangles each.
template <int N>
void bin_lines_points(Topology topology, std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipInfo* clip, const ClipPlanes& planes,
                      const Viewport& vp, const SampleExtent& samples, const LinePointShape& shape, FlatVaryings flat, const TileGrid& grid, TriangleBin<N>& bin,
                      BinMemory& memory) {
    bin.clipped.clear();
    bin_pending(bin, memory, 2 * indices.size(), [&] {  // (two triangles a quad)
        TileBounds tiles;
        std::vector<WindowVertex<N>> window;
        assemble_lines_points(topology, indices, post, clip, planes, vp, window);
        auto emit = [&](const ShadedVertex<N>& c0, const ShadedVertex<N>& c1, const ShadedVertex<N>& c2, const ShadedVertex<N>& c3) {
            const auto first = uint32_t(bin.clipped.size());
            bin.clipped.insert(bin.clipped.end(), {c0, c1, c2, c3});
            for (const std::array<uint32_t, 3> tri : {std::array<uint32_t, 3>{0, 1, 2}, std::array<uint32_t, 3>{0, 2, 3}}) {
                std::array<uint32_t, 3> v = {first + tri[0], first + tri[1], first + tri[2]};
                const ShadedVertex<N>&p = bin.clipped[v[0]], &q = bin.clipped[v[1]], &r = bin.clipped[v[2]];
                int64_t area2 = signed_area2(p.X, p.Y, q.X, q.Y, r.X, r.Y);
                if (area2 == 0) continue;
                if (!is_front_facing(area2 < 0, shape.front)) std::swap(v[1], v[2]), area2 = -area2;  // lines and points face front
                add_to_tiles(bin, tiles, grid, TriangleRef{{v[0] | kClippedVertex, v[1] | kClippedVertex, v[2] | kClippedVertex}},
                             bin.clipped[v[0]], bin.clipped[v[1]], bin.clipped[v[2]], pixel_bounds(p, q, r, samples), area2);
            }
        };
        if (topology == Topology::Points) {
            for (const WindowVertex<N>& p : window) point_quad(p, shape, emit);
        } else {
            for (size_t i = 0; i + 1 < window.size(); i += 2)
                line_quad(window[i], window[i + 1], shape, flat.mask, window[i + (flat.first ? 0 : 1)], emit);
        }
        bin.range = tiles.range();
    });
}

}  // namespace softraster
