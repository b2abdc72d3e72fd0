// Lesson 15: shadow mapping. A torus and a ball over a floor under a directional light: the
// shadow map (the light's depth picture), the scene without and with shadows; then the bias:
// none (acne), right, and too much (the shadow comes loose).
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "shadow.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160, kMap = 256;

struct Object {
    std::vector<MeshIn> vertices;
    std::vector<uint32_t> indices;
    glm::mat4 model;
    glm::vec3 albedo;
};

Canvas draw(const std::vector<Object>& scene, const glm::vec3& to_light, const ShadowMap* map, float bias) {
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    const glm::mat4 camera = perspective(40.0f, 1.0f, 0.1f, 30.0f) * look_at({0, 3.2f, 5.5f}, {0, 0.3f, 0}, {0, 1, 0});
    for (const Object& o : scene)
        ctx.draw(softraster::Topology::Triangles, ShadowedShader{o.model, camera, to_light, o.albedo, map, bias},
                 std::span<const MeshIn>(o.vertices), std::span<const uint32_t>(o.indices));
    return to_canvas(ctx.read_pixels());
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const softraster::Mesh floor = softraster::make_plane(6.0, 1), torus = softraster::make_torus(0.55, 0.2, 24, 48),
                           ball = softraster::make_uv_sphere(0.4, 16, 32);
    const std::vector<Object> scene = {
        {mesh_vertices(floor), floor.indices, glm::mat4(1.0f), {0.8f, 0.8f, 0.75f}},
        {mesh_vertices(torus), torus.indices,
         glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f, 0.8f, 0.0f)) * glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(1, 0, 0)),
         {0.9f, 0.45f, 0.2f}},
        {mesh_vertices(ball), ball.indices, glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, 0.5f, 0.6f)), {0.3f, 0.5f, 0.9f}}};
    // A directional light from the upper left: an orthographic camera looking along the
    // light, framing the floor.
    const glm::vec3 to_light = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f));
    const glm::mat4 light = orthographic(3.5f, 3.5f, 0.1f, 20.0f) * look_at(to_light * 8.0f, {0, 0, 0}, {0, 1, 0});
    std::vector<Placed> placed;
    for (const Object& o : scene) placed.push_back({&o.vertices, &o.indices, o.model});
    const ShadowMap map = render_shadow_map(placed, light, kMap);

    Canvas depth(kMap, kMap);
    float nearest = 1.0f, farthest = 0.0f;
    for (float d : map.depth)
        if (d < 1.0f) nearest = std::min(nearest, d), farthest = std::max(farthest, d);
    for (int y = 0; y < kMap; ++y)
        for (int x = 0; x < kMap; ++x)
            if (const float d = map.depth[size_t(y * kMap + x)]; d < 1.0f) {  // near the light light, far dark
                const auto g = uint8_t(std::lround(40.0f + 215.0f * (farthest - d) / (farthest - nearest)));
                depth.set(x, y, {g, g, g});
            }
    Canvas small_depth(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) small_depth.set(x, y, depth.get(x * kMap / kSize, y * kMap / kSize));
    const Canvas without = draw(scene, to_light, nullptr, 0.0f), with = draw(scene, to_light, &map, 0.004f);
    beside({&small_depth, &without, &with}).save(out / "shadow_mapping.png", 2);
    wrote(out / "shadow_mapping.png");
    const Canvas acne = draw(scene, to_light, &map, 0.0f), loose = draw(scene, to_light, &map, 0.05f);
    beside({&acne, &with, &loose}).save(out / "bias.png", 2);
    wrote(out / "bias.png");
    return 0;
}
