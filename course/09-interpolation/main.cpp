// Lesson 9: affine against perspective-correct interpolation. A checkerboard floor going
// away from the camera, two triangles, its texture coordinates interpolated both ways; and
// one square turned away, as the tutorials show it.
#include <cmath>

#include "../03-triangles/fill.h"
#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "interpolate.h"

using namespace course;

namespace {

constexpr int kW = 200, kH = 150;

struct Corner {
    glm::vec3 position;
    float u, v;
};

// Draws the quad (a, b, c, d) as two triangles, each pixel colored by a checkerboard of
// 8 x 8 squares at its interpolated (u, v).
Canvas draw_quad(const glm::mat4& view_projection, const Corner (&quad)[4], bool perspective_correct) {
    Canvas canvas(kW, kH);
    const int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& t : triangles) {
        Point s[3];
        std::array<float, 3> u, v, w;
        for (int k = 0; k < 3; ++k) {
            const Corner& c = quad[t[k]];
            const glm::vec4 clip = view_projection * glm::vec4(c.position, 1.0f);
            const ScreenPoint p = to_screen(clip, kW, kH);
            s[k] = {std::lround(p.x * kSub), std::lround(p.y * kSub)};
            u[size_t(k)] = c.u, v[size_t(k)] = c.v, w[size_t(k)] = clip.w;
        }
        const double area = double(edge_function(s[0], s[1], s[2]));
        fill_edge_functions(s[0], s[1], s[2], kW, kH, [&](int x, int y) {
            const Point p = pixel_center(x, y);
            const std::array<double, 3> l = {double(edge_function(s[1], s[2], p)) / area, double(edge_function(s[2], s[0], p)) / area,
                                             double(edge_function(s[0], s[1], p)) / area};
            const float pu = perspective_correct ? interpolate_perspective(l, u, w) : interpolate_affine(l, u);
            const float pv = perspective_correct ? interpolate_perspective(l, v, w) : interpolate_affine(l, v);
            const bool dark = (int(std::floor(pu * 8.0f)) + int(std::floor(pv * 8.0f))) % 2 != 0;
            canvas.set(x, y, dark ? kBlue : kWhite);
        });
    }
    return canvas;
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const glm::mat4 camera = perspective(60.0f, float(kW) / float(kH), 0.1f, 100.0f) * look_at({0, 1, 2}, {0, 0, -4}, {0, 1, 0});
    const Corner floor[4] = {{{-3, 0, 1}, 0, 0}, {{3, 0, 1}, 1, 0}, {{3, 0, -12}, 1, 1}, {{-3, 0, -12}, 0, 1}};
    const Canvas floor_affine = draw_quad(camera, floor, false), floor_correct = draw_quad(camera, floor, true);
    beside({&floor_affine, &floor_correct}).save(out / "floor.png", 2);
    wrote(out / "floor.png");
    // A square turned 60 degrees away about its vertical axis.
    const glm::mat4 front = perspective(45.0f, float(kW) / float(kH), 0.1f, 100.0f) * look_at({0, 0, 3.2f}, {0, 0, 0}, {0, 1, 0});
    const float c = std::cos(glm::radians(60.0f)), s = std::sin(glm::radians(60.0f));
    const Corner square[4] = {{{-c, -1, s}, 0, 0}, {{c, -1, -s}, 1, 0}, {{c, 1, -s}, 1, 1}, {{-c, 1, s}, 0, 1}};
    const Canvas square_affine = draw_quad(front, square, false), square_correct = draw_quad(front, square, true);
    beside({&square_affine, &square_correct}).save(out / "square.png", 2);
    wrote(out / "square.png");
    return 0;
}
