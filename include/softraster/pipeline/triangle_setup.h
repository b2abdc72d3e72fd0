// Stage 7, triangle setup: everything the rasterizer needs to walk a triangle in one tile.
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
// they change fast (a texture far away). The planes are computed in double precision and
// then rebased to the tile being drawn, whose pixels are at most 64 apart, so the per-pixel
// arithmetic can be float without losing the low bits of 1/w near a horizon (where a
// ground plane clipped at the near plane has 1/w spanning orders of magnitude).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "softraster/pipeline/culling.h"
#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/sample_pattern.h"
#include "softraster/pipeline/vertex_processing.h"
#include "softraster/render_state.h"

namespace softraster {

// An attribute's plane, relative to the center of the rectangle's first pixel (i, j = 0).
struct Plane {
    float a0 = 0, dadx = 0, dady = 0;
    // at one pixel (float) or at eight (simd::f8), the same arithmetic either way
    template <class T>
    T at(T i, T j) const { return a0 + dadx * i + dady * j; }
};

// Window depth's plane, whose value at the origin is kept in two floats (hi + lo, the
// double-precision setup value split): far from the camera window depths differ from 1 in
// their last bits only, and a0 rounded to one float would put up to half a unit in the last
// place of error into every pixel of the tile, the same for the whole tile (blocks along
// the crossing of two far planes). Summing the small terms first and adding hi last rounds
// once: z is the exact plane rounded to float, to within a tiny fraction of a unit.
struct DepthPlane {
    float hi = 0, lo = 0, dadx = 0, dady = 0;
    template <class T>
    T at(T i, T j) const { return hi + ((lo + dadx * i) + dady * j); }
};

// A draw's settings for its planes (RenderState): polygon offset, and noperspective
// interpolation, for which the varyings' planes are of the varyings themselves and 1/w's plane
// is 1, so that interpolation.h's division leaves them affine in window space.
struct PlaneOptions {
    float offset_factor = 0.0f, offset_units = 0.0f;
    bool noperspective = false;
    bool provoking_first = false;  // flat varyings come from the first corner, not the last
    bool find_constant = false;    // look for constant varyings (setup_planes; blended draws only)
    static PlaneOptions of(const RenderState& st) {
        return {st.polygon_offset_factor, st.polygon_offset_units, st.noperspective, st.provoking_vertex == ProvokingVertex::First};
    }
};

// What rasterization (rasterization.h) and the depth test need of a set-up triangle,
// whatever its varyings: its edges, bounds and facing, and its depth plane. The loops that
// use nothing more take this part alone, so they are compiled once for every varying count
// (the visibility pass, hidden_surface_removal.h).
struct TriangleEdges {
    std::array<int64_t, 3> A, B, C;  // E_i(p) = A_i p.x + B_i p.y + C_i, p in 24.8 fixed point
    std::array<int64_t, 3> bias;     // 0 on top-left edges, -1 elsewhere: inside iff E_i + bias_i >= 0
    Rect bounds;                     // pixels to visit: the triangle's bounds within the tile
    int origin_x = 0, origin_y = 0;  // the pixel the planes are relative to
    bool front_facing = true;
    DepthPlane z;                    // window depth (setup_depth_plane)

    int64_t edge(int i, int64_t px, int64_t py) const {
        return A[size_t(i)] * px + B[size_t(i)] * py + C[size_t(i)];
    }
};

// A triangle's interpolation planes, a lane per plane, as setup_planes makes them four at a
// time: lane k < N the varying k over w, lane N 1/w, the rest padding. Stored as the vectors
// come out of the double-precision arithmetic (each plane's value, then its gradients), they
// need no transpose into one (a0, dadx, dady) record per plane.
template <int N>
struct PlaneLanes {
    static constexpr int kVectors = (N + 1 + 3) / 4;  // four planes a vector
    alignas(16) std::array<float, size_t(4 * kVectors)> a0{}, dadx{}, dady{};
    Plane operator[](size_t k) const { return {a0[k], dadx[k], dady[k]}; }
    void set(size_t k, const Plane& p) { a0[k] = p.a0, dadx[k] = p.dadx, dady[k] = p.dady; }
};

template <int N>
struct TriangleSetup : TriangleEdges {
    std::array<const ShadedVertex<N>*, 3> corner{};  // clockwise on screen
    const ShadedVertex<N>* provoking = nullptr;     // the corner flat varyings come from
    // Interpolation planes, made by setup_planes. A draw may make them only once the triangle
    // is known to cover a sample: in a million-triangle mesh many triangles cover none.
    bool has_planes = false;
    // Every varying has the same value at the three corners (or is flat): then its plane holds
    // the values themselves as constant planes, and interpolation returns them exactly.
    // Only draws that set up planes with Constant (setup_planes) look; for the others it
    // stays false. (Beside has_planes, in its padding: the struct keeps its size.)
    bool constant_varyings = false;
    PlaneOptions options;  // set per draw, before setup_coverage
    PlaneLanes<N> planes;
    Plane var_w(size_t k) const { return planes[k]; }  // varying k / w
    Plane inv_w() const { return planes[size_t(N)]; }  // 1/w
};

// Sets up the coverage of triangle (v0, v1, v2), already culled and known to have non-zero
// snapped area, for drawing inside `rect`: edge functions, fill-rule bias, bounds and facing.
// Returns false if none of the samples of `rect` is in its bounding box.
template <int Samples, int N>
bool setup_coverage(const ShadedVertex<N>& v0, const ShadedVertex<N>& v1, const ShadedVertex<N>& v2,
                    FrontFace front, const Rect& rect, TriangleSetup<N>& t) {
    const Rect b = pixel_bounds<Samples>(v0, v1, v2);
    t.bounds = {std::max(rect.x0, b.x0), std::max(rect.y0, b.y0), std::min(rect.x1, b.x1), std::min(rect.y1, b.y1)};
    if (t.bounds.x0 >= t.bounds.x1 || t.bounds.y0 >= t.bounds.y1) return false;
    const int64_t area2 = signed_area2(v0.X, v0.Y, v1.X, v1.Y, v2.X, v2.Y);
    t.front_facing = is_front_facing(/*ccw_on_screen=*/area2 < 0, front);
    t.corner = {&v0, &v1, &v2};
    t.provoking = t.options.provoking_first ? &v0 : &v2;
    if (area2 < 0) std::swap(t.corner[1], t.corner[2]);  // make it clockwise on screen, so that E >= 0 inside
    t.origin_x = rect.x0;
    t.origin_y = rect.y0;
    t.has_planes = false;

    for (size_t i = 0; i < 3; ++i) {
        const ShadedVertex<N>& a = *t.corner[(i + 1) % 3];
        const ShadedVertex<N>& c = *t.corner[(i + 2) % 3];  // edge a -> c is opposite vertex i
        const int64_t dx = int64_t(c.X) - a.X, dy = int64_t(c.Y) - a.Y;
        t.A[i] = -dy;
        t.B[i] = dx;
        t.C[i] = dy * a.X - dx * a.Y;
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        t.bias[i] = top_left ? 0 : -1;
    }
    return true;
}

// Whether every varying but the flat ones has one value at the three corners.
template <uint64_t Flat, int N>
bool constant_varyings(const ShadedVertex<N>& v0, const ShadedVertex<N>& v1, const ShadedVertex<N>& v2) {
    for (size_t k = 0; k < size_t(N); ++k)
        if (!((Flat >> k) & 1) && !(v0.var[k] == v1.var[k] && v1.var[k] == v2.var[k])) return false;
    return true;
}

// A triangle's plane basis: plane gradients by Cramer's rule on the two edge vectors from
// corner 0, in double, and the offset from that corner of the center of the rectangle's
// first pixel (the planes' origin).
struct PlaneBasis {
    double x1, y1, x2, y2, inv_det, ox, oy;
    // The plane of the values a0, a1, a2 at the corners: its value at the origin pixel and its
    // gradients, in double (T: a double, or a vector of them, one plane per lane).
    template <class T>
    std::array<T, 3> at_origin(T a0, T a1, T a2) const {
        static_assert(!std::is_same_v<T, float>, "planes are made in double precision");
        const T d1 = a1 - a0, d2 = a2 - a0;
        const T dadx = (d1 * y2 - d2 * y1) * inv_det, dady = (d2 * x1 - d1 * x2) * inv_det;
        return {a0 + dadx * ox + dady * oy, dadx, dady};
    }
};
template <int N>
PlaneBasis plane_basis(const TriangleSetup<N>& t) {
    const WindowPosition &w0 = t.corner[0]->window, &w1 = t.corner[1]->window, &w2 = t.corner[2]->window;
    const double x1 = double(w1.x) - w0.x, y1 = double(w1.y) - w0.y;
    const double x2 = double(w2.x) - w0.x, y2 = double(w2.y) - w0.y;
    const double det = x1 * y2 - x2 * y1;
    const double inv_det = det != 0.0 ? 1.0 / det : 0.0;  // unsnapped sliver: flat planes
    return {x1, y1, x2, y2, inv_det, t.origin_x + 0.5 - w0.x, t.origin_y + 0.5 - w0.y};
}

// Window depth's plane, with the draw's polygon offset: all the depth test needs (the
// visibility pass makes this plane alone).
template <int N>
void setup_depth_plane(TriangleSetup<N>& t, const PlaneBasis& basis) {
    const WindowPosition &w0 = t.corner[0]->window, &w1 = t.corner[1]->window, &w2 = t.corner[2]->window;
    auto [z0, dzdx, dzdy] = basis.at_origin<double>(w0.z, w1.z, w2.z);
    if (t.options.offset_factor != 0.0f || t.options.offset_units != 0.0f) {
        // glPolygonOffset for a float depth buffer: the slope m = max(|dz/dx|, |dz/dy|) and the
        // minimum resolvable difference r = 2^(e - 23), e the exponent of the largest |z| of
        // the corners (OpenGL 4.6, section 14.6.5; llvmpipe computes the same). Not clamped:
        // a fragment pushed below 0 or past 1 keeps that depth.
        const float zmax = std::max({std::fabs(w0.z), std::fabs(w1.z), std::fabs(w2.z)});
        int e = 0;
        std::frexp(zmax, &e);  // zmax = f * 2^e with f in [0.5, 1): its float exponent is e - 1
        const double r = zmax > 0.0f ? std::ldexp(1.0, e - 1 - 23) : 0.0;
        z0 += double(t.options.offset_factor) * std::max(std::fabs(dzdx), std::fabs(dzdy)) + double(t.options.offset_units) * r;
    }
    const float z_hi = float(z0);
    t.z = DepthPlane{z_hi, float(z0 - double(z_hi)), float(dzdx), float(dzdy)};
}

// setup_planes' arithmetic for the varyings and 1/w, four planes at a time: each plane a
// lane of four-double vectors, through PlaneBasis::at_origin (lane by lane the operations of
// one plane, in its order: the same bits). The lanes, in order: the N varyings (over w, or
// themselves for noperspective), 1/w (the plane of 1 over w), then unused lanes. (Depth stays apart, in
// setup_depth_plane: in a lane of its own vector it came later, and the rasterizer waits
// on it first.)
namespace plane_lanes {
using d4 = double __attribute__((vector_size(32)));
using simd::f4;

// Lane I's value at corner v before the division by w, as a float: a varying or 1.
template <int N, int I>
float corner_value(const ShadedVertex<N>& v) {
    if constexpr (I < N) return v.var[size_t(I)];
    else if constexpr (I == N) return 1.0f;
    else return 0.0f;
}
// Vector Q's values at corner v. Varyings four in a row are one load; the last vector's are a
// shuffle of the last four varyings, loaded together, with 1 and 0s: its lanes stored one
// by one and loaded as a vector would wait for the stores to reach the cache.
template <int N, int Q>
d4 corner(const ShadedVertex<N>& v, double w) {
    f4 f;
    if constexpr (4 * Q + 4 <= N) {
        std::memcpy(&f, &v.var[size_t(4 * Q)], sizeof f);
    } else if constexpr (N >= 4) {
        f4 last;
        std::memcpy(&last, &v.var[size_t(N - 4)], sizeof last);
        const f4 extra{1.0f, 0.0f, 0.0f, 0.0f};
        constexpr auto from = [](int i) { return i < N ? i - (N - 4) : 4 + std::min(i - N, 1); };
        f = __builtin_shufflevector(last, extra, from(4 * Q), from(4 * Q + 1), from(4 * Q + 2), from(4 * Q + 3));
    } else {
        f = f4{corner_value<N, 4 * Q>(v), corner_value<N, 4 * Q + 1>(v), corner_value<N, 4 * Q + 2>(v), corner_value<N, 4 * Q + 3>(v)};
    }
    return __builtin_convertvector(f, d4) * w;
}
}  // namespace plane_lanes

// Makes the interpolation planes of a triangle whose coverage is set up: depth, 1/w and the
// varyings. Flat: the shader's flat varyings (shader.h), whose planes are the provoking
// vertex's value, constant.
// Constant: compiled to look for constant varyings (constant_varyings above), which it does
// when the draw asks (options.find_constant). A draw decides once, and every path of the
// draw interpolates with the same choice (interpolate_perspective), so a pixel's value never
// depends on the path that drew it. Only blended draws whose shaders read varyings alone
// look (tile_back_end.h): they shade such a triangle once; elsewhere the test and its
// branch would cost without a gain.
template <uint64_t Flat = 0, bool Constant = false, int N>
void setup_planes(TriangleSetup<N>& t) {
    const PlaneBasis basis = plane_basis(t);
    setup_depth_plane(t, basis);
    const ShadedVertex<N>&v0 = *t.corner[0], &v1 = *t.corner[1], &v2 = *t.corner[2];
    // A triangle whose corners carry equal varyings (a flat-shaded face's normal, a plane's
    // normal, one color) has them everywhere: (a/w)/(1/w) = a exactly in real numbers, and
    // taking a itself avoids the rounding of that division (and the division). A smooth
    // mesh's triangle usually differs in its first varying: the search stops there.
    if (Constant && t.options.find_constant) {
        t.constant_varyings = constant_varyings<Flat>(v0, v1, v2);
        if (t.constant_varyings) {
            t.planes.set(size_t(N), Plane{1.0f, 0.0f, 0.0f});
            for (size_t k = 0; k < size_t(N); ++k) t.planes.set(k, Plane{t.provoking->var[k], 0.0f, 0.0f});
            t.has_planes = true;
            return;
        }
    }
    using namespace plane_lanes;
    const bool perspective = !t.options.noperspective;
    auto w = [&](const ShadedVertex<N>& v) { return perspective ? double(v.window.inv_w) : 1.0; };
    [&]<int... Q>(std::integer_sequence<int, Q...>) {
        ([&] {
            const d4 a0 = corner<N, Q>(v0, w(v0)), a1 = corner<N, Q>(v1, w(v1)), a2 = corner<N, Q>(v2, w(v2));
            const auto [value, dadx, dady] = basis.at_origin(a0, a1, a2);
            const f4 a = __builtin_convertvector(value, f4), x = __builtin_convertvector(dadx, f4), y = __builtin_convertvector(dady, f4);
            std::memcpy(&t.planes.a0[size_t(4 * Q)], &a, sizeof a);
            std::memcpy(&t.planes.dadx[size_t(4 * Q)], &x, sizeof x);
            std::memcpy(&t.planes.dady[size_t(4 * Q)], &y, sizeof y);
        }(), ...);
    }(std::make_integer_sequence<int, PlaneLanes<N>::kVectors>());
    // (noperspective: 1/w's lane, made from 1 at every corner, set to exactly 1 everywhere,
    // whatever a sliver's huge 1 / det made of its gradients)
    if (!perspective) t.planes.set(size_t(N), Plane{1.0f, 0.0f, 0.0f});
    for (size_t k = 0; k < size_t(N); ++k)
        if ((Flat >> k) & 1) t.planes.set(k, Plane{t.provoking->var[k], 0.0f, 0.0f});
    t.has_planes = true;
}

// Both: the whole setup of triangle (v0, v1, v2) for drawing inside `rect`. Returns false if
// none of the samples of `rect` is in its bounding box.
template <int Samples, int N>
bool setup_triangle(const ShadedVertex<N>& v0, const ShadedVertex<N>& v1, const ShadedVertex<N>& v2,
                    FrontFace front, const Rect& rect, TriangleSetup<N>& t) {
    if (!setup_coverage<Samples>(v0, v1, v2, front, rect, t)) return false;
    setup_planes(t);
    return true;
}

}  // namespace softraster
