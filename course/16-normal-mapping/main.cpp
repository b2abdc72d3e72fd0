// Lesson 16: normal mapping. The same sphere and the same floor, each lit with its own
// normals and with a normal map of round bumps; and the normal map itself.
#include <vector>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "normal_map.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160;

Canvas draw(softraster::Mesh mesh, const glm::vec3& eye, const glm::vec3& target, const glm::vec3& to_light, const TexelImage* map, float repeats) {
    softraster::generate_tangents(mesh);  // (T along +u at every vertex, from the uvs)
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    const NormalMappedShader shader{glm::mat4(1.0f), perspective(40.0f, 1.0f, 0.1f, 30.0f) * look_at(eye, target, {0, 1, 0}), eye,
                                    glm::normalize(to_light), {0.75f, 0.55f, 0.35f}, map, repeats};
    ctx.draw(softraster::Topology::Triangles, shader, std::span<const softraster::TangentVertex>(mesh.tangent_vertices),
             std::span<const uint32_t>(mesh.indices));
    return to_canvas(ctx.read_pixels());
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const TexelImage map = bumps_normal_map(128);
    Canvas picture(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::u8vec4 t = map.texels[size_t((kSize - 1 - y) * 128 / kSize) * 128 + size_t(x * 128 / kSize)];
            picture.set(x, y, {t.r, t.g, t.b});
        }
    const softraster::Mesh sphere = softraster::make_uv_sphere(1.0, 32, 64);
    const glm::vec3 eye(0, 0.5f, 4.0f), light(-1.0f, 0.8f, 0.7f);
    const Canvas plain = draw(sphere, eye, {0, 0, 0}, light, nullptr, 1.0f), bumpy = draw(sphere, eye, {0, 0, 0}, light, &map, 4.0f);
    beside({&picture, &plain, &bumpy}).save(out / "sphere.png", 2);
    wrote(out / "sphere.png");
    // A floor, the light low from the left: the bumps cast their light and dark sides.
    const softraster::Mesh floor = softraster::make_plane(4.0, 4);
    const glm::vec3 high(0, 3.0f, 3.0f), low_light(-1.0f, 0.35f, 0.0f);
    const Canvas floor_plain = draw(floor, high, {0, 0, 0}, low_light, nullptr, 1.0f), floor_bumpy = draw(floor, high, {0, 0, 0}, low_light, &map, 2.0f);
    beside({&floor_plain, &floor_bumpy}).save(out / "floor.png", 2);
    wrote(out / "floor.png");
    return 0;
}
