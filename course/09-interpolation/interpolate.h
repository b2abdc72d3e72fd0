// Lesson 9: carrying values (colors, texture coordinates) across a triangle. At a pixel with
// screen-space barycentric weights (l0, l1, l2) (lesson 3), for values a0, a1, a2 at the
// corners whose clip-space w (lesson 6: the depth in front of the camera) are w0, w1, w2.
#pragma once
#include <array>

namespace course {

// The barycentric weights (l0, l1, l2) of the point (px, py) in the triangle whose corners
// are at (x[k], y[k]) on the screen (lesson 3's edge functions over the area, here on the
// unsnapped positions, in double precision, as a GPU builds its attribute planes).
struct ScreenWeights {
    double x[3], y[3];
    double edge(int i, int j, double px, double py) const { return (x[j] - x[i]) * (py - y[i]) - (y[j] - y[i]) * (px - x[i]); }
    double area() const { return edge(0, 1, x[2], y[2]); }
    std::array<double, 3> at(double px, double py) const {
        const double a = area();
        return {edge(1, 2, px, py) / a, edge(2, 0, px, py) / a, edge(0, 1, px, py) / a};
    }
};

// Affine (线性插值, in screen space): weight the values as the pixel's position weights the
// corners. Right for depth (lesson 5), wrong for anything painted on the surface under a
// perspective camera: equal steps on the screen are not equal steps on the surface.
inline float interpolate_affine(const std::array<double, 3>& l, const std::array<float, 3>& a) {
    return float(l[0] * a[0] + l[1] * a[1] + l[2] * a[2]);
}

// Perspective-correct (透视校正插值): a / w and 1 / w are linear across the screen (the
// projection divides by w, and so a plane's a / w is affine in x / w and y / w), so
// interpolate both affinely and divide:
//   a = (sum l_i a_i / w_i) / (sum l_i / w_i).
inline float interpolate_perspective(const std::array<double, 3>& l, const std::array<float, 3>& a, const std::array<float, 3>& w) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < 3; ++i) num += l[i] * a[i] / w[i], den += l[i] / w[i];
    return float(num / den);
}

}  // namespace course
