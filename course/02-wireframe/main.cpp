// Lesson 2: a wireframe model. A mesh is vertices and triangles; project each vertex to the
// screen by dropping z (an orthographic view), and draw every triangle's three edges with
// lesson 1's Bresenham.
#include <cmath>

#include <glm/glm.hpp>

#include "../01-lines/lines.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

// Model space -> screen: turn the model (so that we see it from above and the side), drop z,
// and map x, y in [-1, 1] to the picture, y flipped (the model's y goes up, the picture's
// rows go down).
glm::ivec2 to_screen(const glm::vec3& p, int size) {
    const float a = glm::radians(35.0f), b = glm::radians(25.0f);
    const glm::vec3 turned(p.x * std::cos(b) + p.z * std::sin(b), p.y, -p.x * std::sin(b) + p.z * std::cos(b));
    const glm::vec3 tilted(turned.x, turned.y * std::cos(a) - turned.z * std::sin(a), turned.y * std::sin(a) + turned.z * std::cos(a));
    return {int(std::lround((tilted.x + 1.0f) * 0.5f * float(size - 1))), int(std::lround((1.0f - tilted.y) * 0.5f * float(size - 1)))};
}

void draw_wireframe(const softraster::Mesh& mesh, Canvas& canvas, Color color) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const glm::ivec2 a = to_screen(mesh.vertices[mesh.indices[t + size_t(e)]].position, canvas.width());
            const glm::ivec2 b = to_screen(mesh.vertices[mesh.indices[t + size_t((e + 1) % 3)]].position, canvas.width());
            line_bresenham(a.x, a.y, b.x, b.y, [&](int x, int y) { canvas.set(x, y, color); });
        }
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    Canvas torus(200, 200), sphere(200, 200);
    draw_wireframe(softraster::make_torus(0.62, 0.3, 10, 24), torus, kYellow);
    draw_wireframe(softraster::make_uv_sphere(0.9, 12, 24), sphere, kGreen);
    beside({&torus, &sphere}).save(out / "wireframes.png", 2);
    wrote(out / "wireframes.png");
    return 0;
}
