// Stage 3, clipping in homogeneous clip space (before the perspective divide).
//
// A point p is inside plane P when dot(P, p) >= 0. The view volume is -w <= x, y, z <= w.
// Triangles are clipped against near and far exactly (a triangle that reaches behind the eye
// must never be divided by w <= 0), and against the sides of a guard band a little larger
// than the viewport instead of the viewport itself: the rasterizer's scissor discards what
// lies outside the picture, so the image is the same, and nearly every triangle that crosses
// a side of the screen is drawn unclipped.
//
// Triangles: Sutherland–Hodgman (Sutherland & Hodgman 1974), one plane at a time, producing
// a convex polygon of at most 3 + 6 vertices that is then fanned into triangles. Each new
// vertex is interpolated from the edge's inside end toward its outside end, so two triangles
// sharing an edge compute bit-identical new vertices there (no cracks).
// Lines: the parametric clipper of Liang & Barsky (1984) in homogeneous form.
#pragma once
#include <algorithm>
#include <array>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace softraster {

template <int N>
struct ClipVertex {
    glm::vec4 position;        // homogeneous clip coordinates
    std::array<float, N> var;  // varyings
};

// How far the guard band reaches beyond each side of the viewport, in pixels. It bounds
// window coordinates, which keeps 24.8 fixed-point edge functions exact in 64-bit integers.
inline constexpr float kGuardBandPixels = 8192.0f;

class ClipPlanes {
public:
    static constexpr int kCount = 6;

    ClipPlanes() : ClipPlanes(1.0f, 1.0f) {}  // the exact view volume
    // The exact view volume.
    static ClipPlanes frustum() { return {1.0f, 1.0f}; }
    // near, far, and x/y sides widened by the guard band for a viewport of this size.
    static ClipPlanes for_viewport(int width, int height) {
        return {1.0f + 2.0f * kGuardBandPixels / float(width), 1.0f + 2.0f * kGuardBandPixels / float(height)};
    }

    // near z >= -w, far z <= w, left x >= -gx w, right x <= gx w, bottom y >= -gy w, top y <= gy w
    const std::array<glm::vec4, kCount>& planes() const { return planes_; }

    // The six dot products dot(P_i, p), in the order of planes(), for one point (T: float) or
    // eight (simd::f8). Each plane has two zero coefficients, whose terms are exact zeros that
    // change a sum at most in the sign of a zero, so each dot product is one addition: for
    // finite p the same bits as the clipper's glm::dot, (P.x p.x + P.y p.y) + (P.z p.z + P.w p.w),
    // so outcodes and the clipper agree on every side (ClipPlanes.DistancesAreTheDotProducts).
    template <class T>
    std::array<T, kCount> distances(T x, T y, T z, T w) const {
        const T gwx = planes_[2].w * w, gwy = planes_[4].w * w;  // (the sides' reach: x within gx w, y within gy w)
        return {z + w, w - z, x + gwx, gwx - x, y + gwy, gwy - y};
    }
    // Bit i set when p is outside plane i (Cohen–Sutherland style outcode).
    unsigned outcode(const glm::vec4& p) const {
        const std::array<float, kCount> d = distances(p.x, p.y, p.z, p.w);
        unsigned code = 0;
        for (size_t i = 0; i < size_t(kCount); ++i) code |= unsigned(d[i] < 0.0f) << i;
        return code;
    }

private:
    ClipPlanes(float gx, float gy)
        : planes_{{glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, -1, 1), glm::vec4(1, 0, 0, gx), glm::vec4(-1, 0, 0, gx), glm::vec4(0, 1, 0, gy),
                   glm::vec4(0, -1, 0, gy)}} {}
    std::array<glm::vec4, kCount> planes_;
};

template <int N>
ClipVertex<N> lerp_clip_vertex(const ClipVertex<N>& a, const ClipVertex<N>& b, float t) {
    ClipVertex<N> r;
    r.position = a.position + t * (b.position - a.position);
    for (int k = 0; k < N; ++k) r.var[size_t(k)] = a.var[size_t(k)] + t * (b.var[size_t(k)] - a.var[size_t(k)]);
    return r;
}

template <int N>
struct ClipPolygon {
    static constexpr int kMaxVertices = 3 + ClipPlanes::kCount;
    std::array<ClipVertex<N>, kMaxVertices> v;
    int count = 0;
};

// Clips triangle (a, b, c) to the planes selected in `mask`; the result keeps the winding.
// Returns the number of polygon vertices (0 when nothing is left).
template <int N>
int clip_triangle(const ClipVertex<N>& a, const ClipVertex<N>& b, const ClipVertex<N>& c,
                  const ClipPlanes& cp, unsigned mask, ClipPolygon<N>& out) {
    ClipPolygon<N> tmp;
    ClipPolygon<N>* src = &tmp;
    ClipPolygon<N>* dst = &out;
    src->v[0] = a;
    src->v[1] = b;
    src->v[2] = c;
    src->count = 3;
    for (int p = 0; p < ClipPlanes::kCount; ++p) {
        if (!(mask & (1u << p))) continue;
        const glm::vec4 plane = cp.planes()[size_t(p)];
        dst->count = 0;
        for (int i = 0; i < src->count; ++i) {
            const ClipVertex<N>& cur = src->v[size_t(i)];
            const ClipVertex<N>& next = src->v[size_t((i + 1) % src->count)];
            const float dc = glm::dot(plane, cur.position);
            const float dn = glm::dot(plane, next.position);
            if (dc >= 0.0f) dst->v[size_t(dst->count++)] = cur;
            if ((dc >= 0.0f) != (dn >= 0.0f)) {
                // Always from the inside end: t = d_in / (d_in - d_out), in [0, 1].
                dst->v[size_t(dst->count++)] = dc >= 0.0f ? lerp_clip_vertex(cur, next, dc / (dc - dn))
                                                          : lerp_clip_vertex(next, cur, dn / (dn - dc));
            }
        }
        std::swap(src, dst);
        if (src->count < 3) return 0;
    }
    if (src != &out) out = *src;
    return out.count;
}

// Liang–Barsky: shrinks the parameter range [t0, t1] of p0 + t (p1 - p0) plane by plane.
// Returns false when the segment lies entirely outside.
template <int N>
bool clip_line(ClipVertex<N>& p0, ClipVertex<N>& p1, const ClipPlanes& cp) {
    float t0 = 0.0f, t1 = 1.0f;
    for (const glm::vec4& plane : cp.planes()) {
        const float d0 = glm::dot(plane, p0.position);
        const float d1 = glm::dot(plane, p1.position);
        if (d0 < 0.0f && d1 < 0.0f) return false;
        if (d0 < 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
        if (d1 < 0.0f) t1 = std::min(t1, d0 / (d0 - d1));
        if (t0 > t1) return false;
    }
    const ClipVertex<N> a = p0, b = p1;
    if (t0 > 0.0f) p0 = lerp_clip_vertex(a, b, t0);
    if (t1 < 1.0f) p1 = lerp_clip_vertex(a, b, t1);
    return true;
}

}  // namespace softraster
