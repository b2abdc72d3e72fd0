// Rasterization of lines and points.
//
// Lines use a DDA (digital differential analyzer): step one pixel at a time along the major
// axis and take, in each column (or row), the pixel that contains the line at the pixel
// center's coordinate. The segment is half-open, [p0, p1): the pixel at p1 is left to the
// next segment of a strip, as OpenGL's diamond-exit rule does. Depth is interpolated
// linearly in window space and varyings perspective-correctly (t/w, see interpolation.h).
// A point covers the one pixel that contains it.
#pragma once
#include <cmath>

#include "softraster/pipeline/triangle_setup.h"
#include "softraster/pipeline/viewport.h"

namespace softraster {

// Calls on_fragment(x, y, z, t_perspective) for each pixel of the segment inside `rect`;
// t_perspective is the perspective-correct parameter from p0 (0) to p1 (1).
template <int N, class OnFragment>
void rasterize_line(const WindowVertex<N>& p0, const WindowVertex<N>& p1, const Rect& rect, OnFragment&& on_fragment) {
    const float dx = p1.x - p0.x, dy = p1.y - p0.y;
    const bool x_major = std::fabs(dx) >= std::fabs(dy);
    const float a0 = x_major ? p0.x : p0.y, a1 = x_major ? p1.x : p1.y;  // major axis
    const float da = a1 - a0;
    if (da == 0.0f) return;  // zero length
    // Pixel centers c = i + 0.5 with a0 <= c < a1 (or a1 < c <= a0 going backwards).
    const int step = da > 0 ? 1 : -1;
    const int first = da > 0 ? int(std::ceil(a0 - 0.5f)) : int(std::floor(a0 - 0.5f));
    const int last = da > 0 ? int(std::ceil(a1 - 0.5f)) - 1 : int(std::floor(a1 - 0.5f)) + 1;
    for (int i = first; da > 0 ? i <= last : i >= last; i += step) {
        const float t = (float(i) + 0.5f - a0) / da;  // linear in window space
        const float minor = x_major ? p0.y + t * dy : p0.x + t * dx;
        const int x = x_major ? i : int(std::floor(minor));
        const int y = x_major ? int(std::floor(minor)) : i;
        if (x < rect.x0 || x >= rect.x1 || y < rect.y0 || y >= rect.y1) continue;
        const float z = p0.z + t * (p1.z - p0.z);
        const float q0 = (1.0f - t) * p0.inv_w, q1 = t * p1.inv_w;
        on_fragment(x, y, z, q1 / (q0 + q1));
    }
}

template <int N, class OnFragment>
void rasterize_point(const WindowVertex<N>& p, const Rect& rect, OnFragment&& on_fragment) {
    const float fx = std::floor(p.x), fy = std::floor(p.y);
    if (fx < float(rect.x0) || fx >= float(rect.x1) || fy < float(rect.y0) || fy >= float(rect.y1)) return;
    on_fragment(int(fx), int(fy), p.z);
}

}  // namespace softraster
