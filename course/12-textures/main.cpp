// Lesson 12: textures and filtering. A checkerboard floor to the horizon sampled nearest,
// bilinear and trilinear (minification), and a tiny texture blown up nearest and bilinear
// (magnification).
#include <cmath>

#include "../03-triangles/fill.h"
#include "../06-camera/camera.h"
#include "../09-interpolation/interpolate.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "texture.h"

using namespace course;

namespace {

constexpr int kW = 200, kH = 150;

TexelImage checker(int size, int square) {
    TexelImage t{size, size, {}};
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i)
            t.texels.push_back((i / square + j / square) % 2 ? glm::u8vec4(240, 240, 235, 255) : glm::u8vec4(40, 80, 170, 255));
    return t;
}

Color to_color(const glm::vec4& c) {
    return {uint8_t(std::lround(255.0f * c.r)), uint8_t(std::lround(255.0f * c.g)), uint8_t(std::lround(255.0f * c.b))};
}

enum class Filtering { Nearest, Bilinear, Trilinear };

// A square from corners with (u, v) at each, two triangles, perspective-correct (lesson 9);
// the derivatives of (u, v) from the values one pixel to the right and one down.
Canvas draw(const glm::mat4& view_projection, const glm::vec3 (&corner)[4], float repeats, const TexelImage& texture, Filtering f) {
    const std::vector<TexelImage> chain = mipmaps(texture);
    Canvas canvas(kW, kH);
    const glm::vec2 uv[4] = {{0, 0}, {repeats, 0}, {repeats, repeats}, {0, repeats}};
    const int tris[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& t : tris) {
        ScreenWeights weights;
        Point s[3];
        std::array<float, 3> u, v, w;
        for (int k = 0; k < 3; ++k) {
            const glm::vec4 clip = view_projection * glm::vec4(corner[t[k]], 1.0f);
            const ScreenPoint p = to_screen(clip, kW, kH);
            weights.x[k] = p.x, weights.y[k] = p.y, s[k] = {std::lround(p.x * kSub), std::lround(p.y * kSub)};
            u[size_t(k)] = uv[t[k]].x, v[size_t(k)] = uv[t[k]].y, w[size_t(k)] = clip.w;
        }
        auto uv_at = [&](double px, double py) {
            const std::array<double, 3> l = weights.at(px, py);
            return glm::vec2(interpolate_perspective(l, u, w), interpolate_perspective(l, v, w));
        };
        fill_edge_functions(s[0], s[1], s[2], kW, kH, [&](int x, int y) {
            const glm::vec2 here = uv_at(x + 0.5, y + 0.5);
            glm::vec4 c;
            if (f == Filtering::Nearest) c = sample_nearest(texture, here);
            else if (f == Filtering::Bilinear) c = sample_bilinear(texture, here);
            else c = sample_trilinear(chain, here, level_of_detail(texture, uv_at(x + 1.5, y + 0.5) - here, uv_at(x + 0.5, y + 1.5) - here));
            canvas.set(x, y, to_color(c));
        });
    }
    return canvas;
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const TexelImage board = checker(64, 8);
    const glm::mat4 camera = perspective(60.0f, float(kW) / float(kH), 0.1f, 200.0f) * look_at({0, 1, 2}, {0, 0.2f, -4}, {0, 1, 0});
    const glm::vec3 floor[4] = {{-20, 0, 1}, {20, 0, 1}, {20, 0, -60}, {-20, 0, -60}};
    const Canvas nearest = draw(camera, floor, 12.0f, board, Filtering::Nearest), bilinear = draw(camera, floor, 12.0f, board, Filtering::Bilinear),
                 trilinear = draw(camera, floor, 12.0f, board, Filtering::Trilinear);
    beside({&nearest, &bilinear, &trilinear}).save(out / "minification.png", 2);
    wrote(out / "minification.png");
    // Magnified: a 4 x 4 texture of colors over a square filling the view.
    TexelImage tiny{4, 4, {}};
    for (int k = 0; k < 16; ++k) tiny.texels.push_back(glm::u8vec4(k * 17, 255 - k * 13, (k * 5 % 16) * 16, 255));
    const glm::mat4 front = perspective(45.0f, float(kW) / float(kH), 0.1f, 10.0f) * look_at({0, 0, 2.6f}, {0, 0, 0}, {0, 1, 0});
    const glm::vec3 square[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const Canvas big_nearest = draw(front, square, 1.0f, tiny, Filtering::Nearest), big_bilinear = draw(front, square, 1.0f, tiny, Filtering::Bilinear);
    beside({&big_nearest, &big_bilinear}).save(out / "magnification.png", 2);
    wrote(out / "magnification.png");
    return 0;
}
