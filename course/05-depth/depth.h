// Lesson 5: what hides what. The painter's algorithm and the z-buffer, on lesson 3's fill.
// A triangle here is already on the screen: x, y in 1/256 pixel (y down), and a depth z per
// corner, smaller nearer (as a GPU's window depth).
#pragma once
#include <algorithm>
#include <limits>
#include <vector>

#include "../03-triangles/fill.h"
#include "../common/canvas.h"

namespace course {

struct ScreenTriangle {
    Point a, b, c;
    float za, zb, zc;
    Color color;
};

// The depth at a pixel center inside the triangle: the corners' depths weighted by the
// center's barycentric coordinates (lesson 3). Depth after projection is linear across the
// screen, so this is exact (lesson 9 explains why colors and texture coordinates are not).
inline float depth_at(const ScreenTriangle& t, int x, int y) {
    const Point p = pixel_center(x, y);
    const double area = double(edge_function(t.a, t.b, t.c));
    const double u = double(edge_function(t.b, t.c, p)) / area, v = double(edge_function(t.c, t.a, p)) / area;
    return float(u * t.za + v * t.zb + (1.0 - u - v) * t.zc);
}

// The painter's algorithm (画家算法): sort the triangles from far to near by their mean
// depth and draw them in that order, each covering what is behind it, as a painter paints
// the background first.
inline void draw_painter(std::vector<ScreenTriangle> triangles, Canvas& canvas) {
    std::stable_sort(triangles.begin(), triangles.end(), [](const ScreenTriangle& p, const ScreenTriangle& q) {
        return p.za + p.zb + p.zc > q.za + q.zb + q.zc;
    });
    for (const ScreenTriangle& t : triangles)
        fill_edge_functions(t.a, t.b, t.c, canvas.width(), canvas.height(), [&](int x, int y) { canvas.set(x, y, t.color); });
}

// The z-buffer (深度缓冲): keep each pixel's nearest depth so far; a triangle's pixel is
// drawn only where it is nearer than what the pixel holds, in any order of drawing.
// Returns the depth buffer (infinity where nothing was drawn).
inline std::vector<float> draw_z_buffer(const std::vector<ScreenTriangle>& triangles, Canvas& canvas) {
    std::vector<float> depth(size_t(canvas.width()) * size_t(canvas.height()), std::numeric_limits<float>::infinity());
    for (const ScreenTriangle& t : triangles)
        fill_edge_functions(t.a, t.b, t.c, canvas.width(), canvas.height(), [&](int x, int y) {
            const float z = depth_at(t, x, y);
            float& stored = depth[size_t(y) * size_t(canvas.width()) + size_t(x)];
            if (z < stored) {  // the depth test: nearer wins
                stored = z;
                canvas.set(x, y, t.color);
            }
        });
    return depth;
}

}  // namespace course
