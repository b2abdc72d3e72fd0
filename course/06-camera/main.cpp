// Lesson 6: perspective projection and a moving camera. A grid of cubes seen through an
// orthographic and a perspective projection from the same place, and from three places a
// lookAt camera moves to; each drawn with lessons 3-5 (fill, flat shading, culling, z-buffer).
#include <cmath>
#include <vector>

#include "../05-depth/depth.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "camera.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kW = 200, kH = 150;

Canvas draw(const glm::mat4& view, const glm::mat4& projection) {
    static const softraster::Mesh cube = softraster::make_cube(0.8);
    const Color colors[] = {kRed, kGreen, kBlue, kYellow};
    std::vector<ScreenTriangle> triangles;
    for (int gz = 0; gz < 4; ++gz)
        for (int gx = 0; gx < 4; ++gx) {
            const glm::vec3 at(-3.0f + 2.0f * float(gx), 0.0f, -3.0f + 2.0f * float(gz));  // a 4 x 4 grid, 2 apart
            for (size_t t = 0; t + 2 < cube.indices.size(); t += 3) {
                glm::vec3 world[3];
                Point s[3];
                float z[3];
                for (int k = 0; k < 3; ++k) {
                    world[k] = cube.vertices[cube.indices[t + size_t(k)]].position + at;
                    const ScreenPoint p = to_screen(projection * view * glm::vec4(world[k], 1.0f), kW, kH);
                    s[k] = {std::lround(p.x * kSub), std::lround(p.y * kSub)};
                    z[k] = p.depth;
                }
                if (edge_function(s[0], s[1], s[2]) >= 0) continue;  // lesson 4: seen from behind
                const glm::vec3 n = glm::normalize(glm::cross(world[1] - world[0], world[2] - world[0]));
                const float k = 0.25f + 0.75f * std::max(0.0f, glm::dot(n, glm::normalize(glm::vec3(0.5f, 1.0f, 0.7f))));
                const Color c = colors[(gx + gz) % 4];
                triangles.push_back({s[0], s[1], s[2], z[0], z[1], z[2], {uint8_t(c.r * k), uint8_t(c.g * k), uint8_t(c.b * k)}});
            }
        }
    Canvas canvas(kW, kH);
    draw_z_buffer(triangles, canvas);
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
