// Lesson 6: perspective projection and a moving camera. A grid of cubes seen through an
// orthographic and a perspective projection from the same place, and from three places a
// lookAt camera moves to; each drawn with lessons 3-5 (fill, flat shading, culling, z-buffer).
#include <cmath>
#include <vector>

#include "../05-depth/depth.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "camera.h"
#include "cube_grid.h"

using namespace course;

namespace {

constexpr int kW = 200, kH = 150;

Canvas draw(const glm::mat4& view, const glm::mat4& projection) {
    Canvas canvas(kW, kH);
    draw_z_buffer(cube_grid_triangles(projection * view, [](const glm::vec4& clip) { return to_screen(clip, kW, kH); }), canvas);
    return canvas;
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const float aspect = float(kW) / float(kH);
    const glm::mat4 view = look_at({6.0f, 5.0f, 9.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    const Canvas ortho = draw(view, orthographic(4.5f * aspect, 4.5f, 0.1f, 50.0f)), persp = draw(view, perspective(45.0f, aspect, 0.1f, 50.0f));
    beside({&ortho, &persp}).save(out / "orthographic_vs_perspective.png", 2);
    wrote(out / "orthographic_vs_perspective.png");
    // The camera moves: from the front and low, from above (up is then -z, as "up" must not
    // be the direction we look along), and close from the side.
    const glm::mat4 projection = perspective(45.0f, aspect, 0.1f, 50.0f);
    const Canvas low = draw(look_at({0.0f, 1.5f, 11.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}), projection);
    const Canvas above = draw(look_at({0.0f, 12.0f, 0.01f}, {0.0f, 0.0f, 0.0f}, {0, 0, -1}), projection);
    const Canvas side = draw(look_at({-7.0f, 2.0f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0, 1, 0}), projection);
    beside({&low, &above, &side}).save(out / "look_at.png", 2);
    wrote(out / "look_at.png");
    return 0;
}
