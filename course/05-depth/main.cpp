// Lesson 5: the painter's algorithm against the z-buffer: three triangles that overlap in a
// cycle (each partly in front of the next), two that pass through each other, and the
// torus of lesson 4; and the depth buffer itself.
#include <cmath>

#include <glm/glm.hpp>

#include "../common/canvas.h"
#include "../common/lesson.h"
#include "depth.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

Point px(double x, double y) { return {std::lround(x * kSub), std::lround(y * kSub)}; }

Color shade(Color c, float k) { return {uint8_t(c.r * k), uint8_t(c.g * k), uint8_t(c.b * k)}; }

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    constexpr int kSize = 96;
    // Three long triangles in a cycle: red over green over blue over red (each tilted in depth).
    std::vector<ScreenTriangle> cycle_list;
    for (int k = 0; k < 3; ++k) {
        const double a = glm::radians(120.0 * k);
        const double cx = 48 + 30 * std::cos(a), cy = 48 + 30 * std::sin(a);
        const double ex = 48 + 34 * std::cos(a + glm::radians(150.0)), ey = 48 + 34 * std::sin(a + glm::radians(150.0));
        const double nx = -std::sin(a + glm::radians(150.0)) * 7, ny = std::cos(a + glm::radians(150.0)) * 7;
        cycle_list.push_back({px(cx - nx, cy - ny), px(cx + nx, cy + ny), px(ex, ey), 0.2f, 0.2f, 0.8f, k == 0 ? kRed : k == 1 ? kGreen : kBlue});
    }
    const std::vector<ScreenTriangle>& cycle = cycle_list;
    // Two triangles that pass through each other.
    const std::vector<ScreenTriangle> crossing = {{px(10, 20), px(86, 30), px(40, 84), 0.1f, 0.9f, 0.5f, kYellow},
                                                  {px(12, 70), px(84, 18), px(70, 88), 0.8f, 0.2f, 0.5f, kBlue}};
    for (const auto* scene : {&cycle, &crossing}) {
        Canvas painter(kSize, kSize), zbuffer(kSize, kSize);
        draw_painter(*scene, painter);
        draw_z_buffer(*scene, zbuffer);
        const auto name = scene == &cycle ? "cycle.png" : "crossing.png";
        beside({&painter, &zbuffer}).save(out / name, 3);
        wrote(out / name);
    }
    // The torus of lesson 4, every triangle (no culling), by depth; and the depth buffer,
    // near white, far dark.
    const softraster::Mesh torus = softraster::make_torus(0.6, 0.3, 16, 32);
    std::vector<ScreenTriangle> triangles;
    const float a = glm::radians(35.0f), b = glm::radians(25.0f);
    auto turn = [&](glm::vec3 p) {
        const glm::vec3 t(p.x * std::cos(b) + p.z * std::sin(b), p.y, -p.x * std::sin(b) + p.z * std::cos(b));
        return glm::vec3(t.x, t.y * std::cos(a) - t.z * std::sin(a), t.y * std::sin(a) + t.z * std::cos(a));
    };
    constexpr int kTorus = 160;
    for (size_t t = 0; t + 2 < torus.indices.size(); t += 3) {
        glm::vec3 v[3];
        Point s[3];
        float z[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = turn(torus.vertices[torus.indices[t + size_t(k)]].position);
            s[k] = px((v[k].x + 1.0) * 0.5 * kTorus, (1.0 - v[k].y) * 0.5 * kTorus);
            z[k] = 0.5f - 0.5f * v[k].z;  // the viewer looks down -z: larger z is nearer
        }
        const glm::vec3 n = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
        triangles.push_back({s[0], s[1], s[2], z[0], z[1], z[2], shade(kYellow, 0.15f + 0.85f * std::max(0.0f, glm::dot(n, glm::normalize(glm::vec3(-0.4f, 0.7f, 0.8f)))))});
    }
    Canvas painter(kTorus, kTorus), zbuffer(kTorus, kTorus), depth_picture(kTorus, kTorus);
    draw_painter(triangles, painter);
    const std::vector<float> depth = draw_z_buffer(triangles, zbuffer);
    float nearest = 1.0f, farthest = 0.0f;
    for (float d : depth)
        if (std::isfinite(d)) nearest = std::min(nearest, d), farthest = std::max(farthest, d);
    for (int y = 0; y < kTorus; ++y)
        for (int x = 0; x < kTorus; ++x)
            if (const float d = depth[size_t(y * kTorus + x)]; std::isfinite(d)) {
                const auto g = uint8_t(std::lround(40.0f + 215.0f * (farthest - d) / (farthest - nearest)));
                depth_picture.set(x, y, {g, g, g});
            }
    beside({&painter, &zbuffer, &depth_picture}).save(out / "torus.png", 2);
    wrote(out / "torus.png");
    return 0;
}
