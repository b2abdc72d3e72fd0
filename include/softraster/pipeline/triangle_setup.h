// Stage 6, triangle setup: everything the rasterizer needs, computed once per triangle.
//
// Following Giesen, "Triangle rasterization in practice" (2013):
// - vertex positions are snapped to 24.8 fixed point (1/256 pixel, round to nearest);
// - each edge a->b gets an integer edge function
//       E(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x) = A p.x + B p.y + C,
//   exact in 64-bit integers for every point of the guard band (see clipping.h);
// - the triangle is oriented so that E >= 0 inside (clockwise on screen, y down);
// - the top-left fill rule is a bias: on an edge that is neither a top nor a left edge a
//   sample exactly on the edge (E == 0) is outside, i.e. the test becomes E - 1 >= 0.
//   With y down, a top edge is horizontal with the interior below it (dy == 0, dx > 0) and
//   a left edge goes up the screen (dy < 0). Two triangles sharing an edge see it with
//   opposite directions, so exactly one of them owns the samples on it.
// Edge i is the edge opposite vertex i.
//
// Attributes are interpolated with plane equations a(x, y) = a0 + da/dx (x - x0) + da/dy (y - y0)
// built from the unsnapped window positions, as a GPU's setup does: snapping decides
// coverage only, so attributes do not shift by the snapping error, which matters where
// they change fast (a texture far away).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "softraster/pipeline/culling.h"
#include "softraster/pipeline/viewport.h"
#include "softraster/render_state.h"

namespace softraster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixelOne = int64_t(1) << kSubpixelBits;

// Window coordinate (pixels) -> 24.8 fixed point, round to nearest.
inline int64_t snap_to_subpixel(float v) { return int64_t(std::lrint(double(v) * double(kSubpixelOne))); }

// Half-open pixel rectangle [x0, x1) x [y0, y1): the viewport, or a tile of it.
struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// An attribute's plane over window space, relative to the triangle's reference point.
// Double precision: where 1/w spans orders of magnitude across a triangle (a ground plane
// clipped at the near plane and reaching the horizon), float planes lose the low bits of
// 1/w near the horizon and a minified texture aliases differently (conformance near_clip).
struct Plane {
    double a0 = 0, dadx = 0, dady = 0;
    double at(double dx, double dy) const { return a0 + dadx * dx + dady * dy; }
};

template <int N>
struct TriangleSetup {
    std::array<int64_t, 3> A, B, C;  // E_i(p) = A_i p.x + B_i p.y + C_i, p in 24.8 fixed point
    std::array<int64_t, 3> bias;     // 0 on top-left edges, -1 elsewhere: inside iff E_i + bias_i >= 0
    Rect bounds;                     // pixels the triangle may touch, inclusive-exclusive
    double ref_x = 0, ref_y = 0;     // window position of vertex 0: the planes' origin
    Plane z;                         // window depth
    Plane inv_w;                     // 1/w
    std::array<Plane, N> var_w;      // varying / w
    bool front_facing = true;

    int64_t edge(int i, int64_t px, int64_t py) const {
        return A[size_t(i)] * px + B[size_t(i)] * py + C[size_t(i)];
    }
};

// Builds the setup of triangle (v0, v1, v2), or returns false when it is culled, has zero
// snapped area, or does not touch `scissor`.
template <int N>
bool setup_triangle(const WindowVertex<N>& v0, const WindowVertex<N>& v1, const WindowVertex<N>& v2,
                    CullMode cull, FrontFace front, const Rect& scissor, TriangleSetup<N>& t) {
    const WindowVertex<N>* v[3] = {&v0, &v1, &v2};
    int64_t X[3], Y[3];
    for (int i = 0; i < 3; ++i) {
        X[i] = snap_to_subpixel(v[i]->x);
        Y[i] = snap_to_subpixel(v[i]->y);
    }
    int64_t area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
    if (area2 == 0) return false;
    t.front_facing = is_front_facing(/*ccw_on_screen=*/area2 < 0, front);
    if (is_culled(t.front_facing, cull)) return false;
    if (area2 < 0) {  // make it clockwise on screen, so that E >= 0 inside
        std::swap(v[1], v[2]);
        std::swap(X[1], X[2]);
        std::swap(Y[1], Y[2]);
        area2 = -area2;
    }

    // Bounding box in pixels: any sample position inside pixel i lies in [256 i, 256 i + 256).
    const int64_t minx = std::min({X[0], X[1], X[2]}), maxx = std::max({X[0], X[1], X[2]});
    const int64_t miny = std::min({Y[0], Y[1], Y[2]}), maxy = std::max({Y[0], Y[1], Y[2]});
    t.bounds.x0 = int(std::max<int64_t>(scissor.x0, minx >> kSubpixelBits));
    t.bounds.y0 = int(std::max<int64_t>(scissor.y0, miny >> kSubpixelBits));
    t.bounds.x1 = int(std::min<int64_t>(scissor.x1, (maxx >> kSubpixelBits) + 1));
    t.bounds.y1 = int(std::min<int64_t>(scissor.y1, (maxy >> kSubpixelBits) + 1));
    if (t.bounds.x0 >= t.bounds.x1 || t.bounds.y0 >= t.bounds.y1) return false;

    for (int i = 0; i < 3; ++i) {
        const int a = (i + 1) % 3, b = (i + 2) % 3;  // edge a -> b is opposite vertex i
        const int64_t dx = X[b] - X[a], dy = Y[b] - Y[a];
        t.A[size_t(i)] = -dy;
        t.B[size_t(i)] = dx;
        t.C[size_t(i)] = dy * X[a] - dx * Y[a];
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        t.bias[size_t(i)] = top_left ? 0 : -1;
    }

    // Plane gradients by Cramer's rule on the two edge vectors from vertex 0.
    t.ref_x = v[0]->x;
    t.ref_y = v[0]->y;
    const double x1 = double(v[1]->x) - v[0]->x, y1 = double(v[1]->y) - v[0]->y;
    const double x2 = double(v[2]->x) - v[0]->x, y2 = double(v[2]->y) - v[0]->y;
    const double det = x1 * y2 - x2 * y1;
    const double inv_det = det != 0.0 ? 1.0 / det : 0.0;  // unsnapped sliver: flat planes
    auto plane = [&](double a0, double a1, double a2) {
        const double d1 = a1 - a0, d2 = a2 - a0;
        return Plane{a0, (d1 * y2 - d2 * y1) * inv_det, (d2 * x1 - d1 * x2) * inv_det};
    };
    t.z = plane(v[0]->z, v[1]->z, v[2]->z);
    t.inv_w = plane(v[0]->inv_w, v[1]->inv_w, v[2]->inv_w);
    for (size_t k = 0; k < size_t(N); ++k)
        t.var_w[k] = plane(double(v[0]->var[k]) * v[0]->inv_w, double(v[1]->var[k]) * v[1]->inv_w,
                           double(v[2]->var[k]) * v[2]->inv_w);
    return true;
}

}  // namespace softraster
