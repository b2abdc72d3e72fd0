// Lesson 1: two ways to draw a line of pixels from (x0, y0) to (x1, y1), both endpoints
// included, walking from the first to the second. `plot(x, y)` sets one pixel.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace course {

// DDA (digital differential analyzer, 数值微分法): take one pixel step along the longer axis
// and add the slope to the other coordinate, rounding it to the nearest pixel. One addition
// per pixel, but in floating point, and rounding at every step.
template <class Plot>
void line_dda(int x0, int y0, int x1, int y1, Plot plot) {
    const int steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    if (steps == 0) return plot(x0, y0);
    const double step_x = double(x1 - x0) / steps, step_y = double(y1 - y0) / steps;
    double x = x0, y = y0;
    for (int i = 0; i <= steps; ++i) {
        plot(int(std::floor(x + 0.5)), int(std::floor(y + 0.5)));
        x += step_x;
        y += step_y;
    }
}

// Bresenham (布雷森汉姆算法): the same pixels with integers only. Walk along the longer
// axis (swap x and y for steep lines). `error` is how far the line has drifted from the
// current row, in units of 1 / (2 dx) of a pixel: each step adds 2 dy, and once it passes dx
// (half a pixel) the line is nearer the next row, so step there and take 2 dx off.
template <class Plot>
void line_bresenham(int x0, int y0, int x1, int y1, Plot plot) {
    const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
    if (steep) std::swap(x0, y0), std::swap(x1, y1);
    const int dx = std::abs(x1 - x0), dy = std::abs(y1 - y0);
    const int step_x = x1 >= x0 ? 1 : -1, step_y = y1 >= y0 ? 1 : -1;
    int error = 0, y = y0;
    for (int x = x0;; x += step_x) {
        if (steep) plot(y, x);
        else plot(x, y);
        if (x == x1) break;
        error += 2 * dy;
        if (error > dx) {  // past half a pixel (exactly half: stay, a choice; see the lesson)
            y += step_y;
            error -= 2 * dx;
        }
    }
}

// Whether the ideal line passes exactly halfway between two pixel centers at the k-th step
// from (x0, y0) along the longer axis: there both pixels are equally near, and rounding
// rules may pick either (DDA rounds up, Bresenham stays, the GPU follows its fill rule).
inline bool line_tie_at(int x0, int y0, int x1, int y1, int k) {
    const int dx = std::abs(x1 - x0), dy = std::abs(y1 - y0);
    const int major = std::max(dx, dy), minor = std::min(dx, dy);
    return major > 0 && (2 * k * minor) % (2 * major) == major;  // k minor / major = n + 1/2
}

}  // namespace course
