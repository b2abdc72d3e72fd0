// Lesson 10: vertex and fragment shaders with varyings, on the real pipeline. A triangle
// whose corner colors are interpolated; and one torus through four fragment shaders.
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "shaders.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160;

// One draw of a mesh with shader look L into a fresh framebuffer: clear, draw, read.
template <Look L>
Canvas draw(const softraster::Mesh& mesh, const glm::mat4& model, const glm::mat4& view_projection) {
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    const std::vector<MeshIn> vertices = mesh_vertices(mesh);
    ctx.draw(softraster::Topology::Triangles, LessonShader<L>{model, view_projection}, std::span<const MeshIn>(vertices),
             std::span<const uint32_t>(mesh.indices));
    return to_canvas(ctx.read_pixels());  // runs the draw, then reads the picture
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    // A triangle with a red, a green and a blue corner, tilted away from the camera.
    softraster::Mesh triangle;
    triangle.vertices.resize(3);
    triangle.vertices[0].position = {-1.0f, -0.9f, 0.6f}, triangle.vertices[0].color = {1, 0, 0, 1};
    triangle.vertices[1].position = {1.0f, -0.9f, 0.6f}, triangle.vertices[1].color = {0, 1, 0, 1};
    triangle.vertices[2].position = {0.0f, 0.9f, -1.2f}, triangle.vertices[2].color = {0, 0, 1, 1};
    for (auto& v : triangle.vertices) v.normal = {0, 0, 1};
    triangle.indices = {0, 1, 2};
    const glm::mat4 camera = perspective(45.0f, 1.0f, 0.1f, 20.0f) * look_at({0, 0.3f, 3.2f}, {0, 0, 0}, {0, 1, 0});
    draw<Look::VertexColor>(triangle, glm::mat4(1.0f), camera).save(out / "varyings.png", 2);
    wrote(out / "varyings.png");

    const softraster::Mesh torus = softraster::make_torus(0.6, 0.28, 32, 64);
    const glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(50.0f), glm::vec3(1, 0, 0));
    const Canvas normals = draw<Look::Normals>(torus, model, camera), stripes = draw<Look::Stripes>(torus, model, camera),
                 toon = draw<Look::Toon>(torus, model, camera);
    beside({&normals, &stripes, &toon}).save(out / "fragment_shaders.png", 2);
    wrote(out / "fragment_shaders.png");
    return 0;
}
