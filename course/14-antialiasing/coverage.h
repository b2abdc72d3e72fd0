// Lesson 14: anti-aliasing (反走样). How much of a pixel a triangle covers, measured at a few
// sample points instead of only the center (lesson 3's edge functions, with the fill rule).
#pragma once
#include <array>

#include "../03-triangles/fill.h"

namespace course {

// 4x MSAA's sample points inside a pixel, in 1/256 pixel: a rotated grid (旋转网格), so that
// no two share a row or a column, and near-horizontal and near-vertical edges, where aliasing
// shows most, get four different steps (OpenGL's and Direct3D's standard 4x pattern).
inline constexpr std::array<Point, 4> kRotatedGrid = {{{96, 32}, {224, 96}, {32, 160}, {160, 224}}};
// Supersampling 2 x 2: the centers of the four sub-pixels of a picture twice as large.
inline constexpr std::array<Point, 4> kOrderedGrid = {{{64, 64}, {192, 64}, {64, 192}, {192, 192}}};

// How many of the pattern's points in pixel (i, j) lie inside the triangle.
template <size_t N>
int covered_samples(Point a, Point b, Point c, int i, int j, const std::array<Point, N>& pattern) {
    if (!orient(a, b, c)) return 0;
    const int64_t bias_a = fill_rule_bias(b, c), bias_b = fill_rule_bias(c, a), bias_c = fill_rule_bias(a, b);
    int n = 0;
    for (const Point& s : pattern) {
        const Point p{kSub * i + s.x, kSub * j + s.y};
        n += edge_function(b, c, p) - bias_a >= 0 && edge_function(c, a, p) - bias_b >= 0 && edge_function(a, b, p) - bias_c >= 0;
    }
    return n;
}

}  // namespace course
