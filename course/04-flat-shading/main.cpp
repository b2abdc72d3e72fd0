// Lesson 4: flat shading and back-face culling. A torus and a sphere, each triangle one
// color from Lambert's law, drawn in the mesh's order without and with culling.
#include <cmath>

#include <glm/glm.hpp>

#include "../common/canvas.h"
#include "../common/lesson.h"
#include "shade.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160;

// Turned as in lesson 2, then looked at along -z: x right, y up, z towards the viewer.
glm::vec3 turn(const glm::vec3& p) {
    const float a = glm::radians(35.0f), b = glm::radians(25.0f);
    const glm::vec3 t(p.x * std::cos(b) + p.z * std::sin(b), p.y, -p.x * std::sin(b) + p.z * std::cos(b));
    return {t.x, t.y * std::cos(a) - t.z * std::sin(a), t.y * std::sin(a) + t.z * std::cos(a)};
}

// Drop z and map to the picture (lesson 2's viewport), in 1/256 pixel for lesson 3's fill.
Point to_screen(const glm::vec3& p) {
    return {std::lround((p.x + 1.0f) * 0.5f * kSize * kSub), std::lround((1.0f - p.y) * 0.5f * kSize * kSub)};
}

Canvas draw(const softraster::Mesh& mesh, bool cull, Color base) {
    Canvas canvas(kSize, kSize);
    const glm::vec3 to_light(-0.4f, 0.7f, 0.8f);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = turn(mesh.vertices[mesh.indices[t]].position), b = turn(mesh.vertices[mesh.indices[t + 1]].position),
                        c = turn(mesh.vertices[mesh.indices[t + 2]].position);
        const Point sa = to_screen(a), sb = to_screen(b), sc = to_screen(c);
        if (cull && faces_away_on_screen(sa, sb, sc)) continue;
        const float k = 0.15f + 0.85f * lambert(a, b, c, to_light);
        const Color color{uint8_t(base.r * k), uint8_t(base.g * k), uint8_t(base.b * k)};
        fill_edge_functions(sa, sb, sc, kSize, kSize, [&](int x, int y) { canvas.set(x, y, color); });
    }
    return canvas;
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const softraster::Mesh sphere = softraster::make_uv_sphere(0.9, 12, 24), torus = softraster::make_torus(0.6, 0.3, 16, 32);
    const Canvas sphere_all = draw(sphere, false, kGreen), sphere_culled = draw(sphere, true, kGreen);
    beside({&sphere_all, &sphere_culled}).save(out / "sphere_culling.png", 2);
    wrote(out / "sphere_culling.png");
    const Canvas torus_all = draw(torus, false, kYellow), torus_culled = draw(torus, true, kYellow);
    beside({&torus_all, &torus_culled}).save(out / "torus_culling.png", 2);
    wrote(out / "torus_culling.png");
    return 0;
}
