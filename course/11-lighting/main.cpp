// Lesson 11: Gouraud, Phong and Blinn-Phong. A coarse sphere lit per vertex (Gouraud) and per
// pixel with Phong's and with Blinn's highlight; and a plane seen at a grazing angle, where
// the two highlights differ most.
#include <vector>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "lighting.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160;

template <Model M>
Canvas draw(const softraster::Mesh& mesh, const glm::vec3& eye, const glm::vec3& target, const glm::vec3& light, const glm::vec3& albedo) {
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    const std::vector<MeshIn> vertices = mesh_vertices(mesh);
    const LitShader<M> shader{glm::mat4(1.0f), perspective(40.0f, 1.0f, 0.1f, 50.0f) * look_at(eye, target, {0, 1, 0}), eye, light, albedo};
    ctx.draw(softraster::Topology::Triangles, shader, std::span<const MeshIn>(vertices), std::span<const uint32_t>(mesh.indices));
    return to_canvas(ctx.read_pixels());
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const softraster::Mesh sphere = softraster::make_uv_sphere(1.0, 10, 20);
    const glm::vec3 eye(0, 0.4f, 4.2f), light(2.5f, 3.0f, 3.0f), red(0.8f, 0.2f, 0.15f);
    const Canvas gouraud = draw<Model::Gouraud>(sphere, eye, {0, 0, 0}, light, red), phong = draw<Model::Phong>(sphere, eye, {0, 0, 0}, light, red),
                 blinn = draw<Model::BlinnPhong>(sphere, eye, {0, 0, 0}, light, red);
    beside({&gouraud, &phong, &blinn}).save(out / "sphere.png", 2);
    wrote(out / "sphere.png");
    // A floor, the light low ahead and the eye low behind: a grazing highlight.
    const softraster::Mesh floor = softraster::make_plane(8.0, 32);
    const glm::vec3 low_eye(0, 0.5f, 4.0f), low_light(0, 0.6f, -4.0f), gray(0.35f, 0.4f, 0.5f);
    const Canvas floor_phong = draw<Model::Phong>(floor, low_eye, {0, 0, -1}, low_light, gray),
                 floor_blinn = draw<Model::BlinnPhong>(floor, low_eye, {0, 0, -1}, low_light, gray);
    beside({&floor_phong, &floor_blinn}).save(out / "grazing.png", 2);
    wrote(out / "grazing.png");
    return 0;
}
