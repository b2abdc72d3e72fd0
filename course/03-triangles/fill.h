// Lesson 3: three ways to fill a triangle. Positions are in 1/256 of a pixel (as the GPU
// snaps them: 24.8 fixed point), so every test below is exact integer arithmetic; y grows
// downwards and pixel (i, j) has its center at (256 i + 128, 256 j + 128).
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>

namespace course {

inline constexpr int64_t kSub = 256;  // subpixel steps per pixel

struct Point {
    int64_t x, y;  // in 1/256 pixel
};

inline Point pixel_center(int i, int j) { return {kSub * i + kSub / 2, kSub * j + kSub / 2}; }

// The edge function (边函数) of the edge a -> b at p: twice the signed area of the triangle
// (a, b, p). It is 0 on the line through a and b, positive on one side and negative on the
// other (the 2D cross product (b - a) x (p - a)).
inline int64_t edge_function(Point a, Point b, Point p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// The top-left rule (左上规则): a pixel center exactly on an edge belongs to the triangle
// only if the edge is a top edge (horizontal, the triangle below it) or a left edge (the
// triangle to its right). Two triangles that share an edge see it from opposite sides, so
// exactly one of them takes the centers on it. For a triangle turned so that its edge
// functions are >= 0 inside (clockwise on the screen, y down): a top edge runs to the right
// (dy = 0, dx > 0) and a left edge runs up (dy < 0). Other edges need E > 0, i.e. E - 1 >= 0.
inline int64_t fill_rule_bias(Point a, Point b) {
    const bool top = a.y == b.y && b.x > a.x, left = b.y < a.y;
    return top || left ? 0 : 1;
}

// The triangle turned so that its edge functions are positive inside; false when it has no
// area (then nothing is drawn).
inline bool orient(Point& a, Point& b, Point& c) {
    const int64_t area = edge_function(a, b, c);
    if (area == 0) return false;
    if (area < 0) std::swap(b, c);
    return true;
}

// The pixels whose centers may be inside: the triangle's bounding box (包围盒), clamped to the
// picture.
struct PixelBox {
    int x0, y0, x1, y1;  // inclusive
};
inline int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
inline int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }
inline PixelBox pixel_box(Point a, Point b, Point c, int width, int height) {
    // Center i lies in [lo, hi] when 256 i + 128 >= lo and <= hi.
    const int64_t lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
    const int64_t lo_y = std::min({a.y, b.y, c.y}), hi_y = std::max({a.y, b.y, c.y});
    return {int(std::max<int64_t>(0, ceil_div(lo_x - kSub / 2, kSub))), int(std::max<int64_t>(0, ceil_div(lo_y - kSub / 2, kSub))),
            int(std::min<int64_t>(width - 1, floor_div(hi_x - kSub / 2, kSub))),
            int(std::min<int64_t>(height - 1, floor_div(hi_y - kSub / 2, kSub)))};
}

// 1. Bounding box and barycentric coordinates (重心坐标), as tinyrenderer starts: for every
// pixel of the box, its center's weights (u, v, w) with p = u a + v b + w c and u + v + w = 1;
// inside when none is negative. Here the weights are edge functions over the area, and there
// is no fill rule: a center on an edge (weight 0) is drawn by both triangles that share it.
template <class Plot>
void fill_barycentric(Point a, Point b, Point c, int width, int height, Plot plot) {
    const double area = double(edge_function(a, b, c));
    if (area == 0.0) return;
    const PixelBox box = pixel_box(a, b, c, width, height);
    for (int j = box.y0; j <= box.y1; ++j)
        for (int i = box.x0; i <= box.x1; ++i) {
            const Point p = pixel_center(i, j);
            const double u = double(edge_function(b, c, p)) / area, v = double(edge_function(c, a, p)) / area,
                         w = double(edge_function(a, b, p)) / area;
            if (u >= 0.0 && v >= 0.0 && w >= 0.0) plot(i, j);
        }
}

// 2. Edge functions with the fill rule (Pineda 1988; what GPUs and our pipeline do): the same
// box, a center inside when each edge function, less its bias, is >= 0.
template <class Plot>
void fill_edge_functions(Point a, Point b, Point c, int width, int height, Plot plot) {
    if (!orient(a, b, c)) return;
    const int64_t bias_a = fill_rule_bias(b, c), bias_b = fill_rule_bias(c, a), bias_c = fill_rule_bias(a, b);
    const PixelBox box = pixel_box(a, b, c, width, height);
    for (int j = box.y0; j <= box.y1; ++j)
        for (int i = box.x0; i <= box.x1; ++i) {
            const Point p = pixel_center(i, j);
            if (edge_function(b, c, p) - bias_a >= 0 && edge_function(c, a, p) - bias_b >= 0 && edge_function(a, b, p) - bias_c >= 0)
                plot(i, j);
        }
}

// 3. Scanline (扫描线): row by row, find where the row of pixel centers enters the triangle
// and where it leaves, and fill the span between. Each edge the row crosses bounds the span
// on one side: with E(x) = A x + B along the row (A = -(b.y - a.y)), the centers with
// E(x) - bias >= 0 are those right of the crossing when A > 0 (a left edge) and left of it
// when A < 0 (a right edge); a horizontal edge (A = 0) lets the whole row in or none of it.
// The crossing is rounded to a pixel center exactly, with integer division, so the span's
// ends obey the same fill rule as the edge functions. (The classic scanline instead adds
// dx/dy to x from row to row in floating point: fast, but it drifts, and its rounding is
// not the fill rule's.)
template <class Plot>
void fill_scanline(Point a, Point b, Point c, int width, int height, Plot plot) {
    if (!orient(a, b, c)) return;
    const std::pair<Point, Point> edges[3] = {{b, c}, {c, a}, {a, b}};
    const PixelBox box = pixel_box(a, b, c, width, height);
    for (int j = box.y0; j <= box.y1; ++j) {
        const int64_t yc = kSub * j + kSub / 2;
        int64_t first = 0, last = width - 1;  // the span of pixel columns, inclusive
        for (const auto& [p, q] : edges) {
            // E(256 i + 128) = A (256 i + 128) + B' >= bias, with A = -(q.y - p.y).
            const int64_t A = -(q.y - p.y), B = (q.x - p.x) * (yc - p.y) + (q.y - p.y) * p.x;
            const int64_t need = fill_rule_bias(p, q) - B - A * (kSub / 2);  // A * 256 i >= need
            if (A > 0) first = std::max(first, ceil_div(need, A * kSub));
            else if (A < 0) last = std::min(last, floor_div(need, A * kSub));
            else if (need > 0) first = width;  // a horizontal edge the row is on the wrong side of
        }
        for (int64_t i = first; i <= last; ++i) plot(int(i), j);
    }
}

}  // namespace course
