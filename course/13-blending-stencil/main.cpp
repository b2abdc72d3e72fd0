// Lesson 13: blending, draw order and the stencil test, on the real pipeline. Three panes of
// colored glass in front of a wall: drawn far to near, near to far, and added; then a torus
// seen only through a star-shaped hole cut in the stencil buffer.
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "blend.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

namespace {

constexpr int kSize = 160;

const glm::mat4 kCamera = perspective(40.0f, 1.0f, 0.1f, 20.0f) * look_at({0.6f, 0.4f, 5}, {0, 0, 0}, {0, 1, 0});

struct Pane {
    glm::vec3 at;
    glm::vec4 color;
};

// The wall (opaque), then the three panes in the given order with the given blending.
Canvas glass(const std::vector<Pane>& order, softraster::BlendMode blend) {
    static const softraster::Mesh square = softraster::make_plane(1.6, 1);  // (in x-z: turned to face the camera below)
    const std::vector<MeshIn> v = mesh_vertices(square);
    softraster::Framebuffer fb(kSize, kSize);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    ctx.state.cull = softraster::CullMode::None;
    const glm::mat4 face = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    const glm::mat4 wall = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -1.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)) * face;
    ctx.draw(softraster::Topology::Triangles, FlatShader{wall, kCamera, {0.45f, 0.45f, 0.42f, 1.0f}}, std::span<const MeshIn>(v),
             std::span<const uint32_t>(square.indices));
    ctx.state.blend = blend;
    // The glass writes depth here (as an opaque object would), which is what makes the order
    // matter twice over: a near pane drawn first hides the far ones by the depth test.
    ctx.state.depth_write = blend == softraster::BlendMode::Alpha;
    for (const Pane& pane : order) {
        const glm::mat4 model = glm::translate(glm::mat4(1.0f), pane.at) * face;
        ctx.draw(softraster::Topology::Triangles, FlatShader{model, kCamera, pane.color}, std::span<const MeshIn>(v),
                 std::span<const uint32_t>(square.indices));
    }
    return to_canvas(ctx.read_pixels());
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const Pane red{{-0.5f, 0.0f, -0.8f}, {0.9f, 0.15f, 0.1f, 0.5f}}, green{{0.0f, 0.25f, -0.3f}, {0.1f, 0.8f, 0.2f, 0.5f}},
               blue{{0.5f, 0.0f, 0.2f}, {0.15f, 0.3f, 0.95f, 0.5f}};
    const Canvas sorted = glass({red, green, blue}, softraster::BlendMode::Alpha);
    const Canvas unsorted = glass({blue, green, red}, softraster::BlendMode::Alpha);
    const Canvas added = glass({blue, green, red}, softraster::BlendMode::Additive);
    beside({&sorted, &unsorted, &added}).save(out / "draw_order.png", 2);
    wrote(out / "draw_order.png");

    // The stencil: a five-pointed star drawn into the stencil only (no color), then the torus
    // drawn where the stencil is 1.
    std::vector<MeshIn> star;
    std::vector<uint32_t> star_indices;
    star.push_back({{0, 0, 0}, {0, 0, 1}, {1, 1, 1, 1}});
    for (int k = 0; k <= 10; ++k) {
        const float a = glm::radians(90.0f + 36.0f * float(k)), r = k % 2 ? 0.45f : 1.1f;
        star.push_back({{r * std::cos(a), r * std::sin(a), 0}, {0, 0, 1}, {1, 1, 1, 1}});
        if (k > 0) star_indices.insert(star_indices.end(), {0u, uint32_t(k), uint32_t(k + 1)});
    }
    const softraster::Mesh torus = softraster::make_torus(0.8, 0.35, 32, 64);
    const std::vector<MeshIn> torus_vertices = mesh_vertices(torus);
    const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(1, 0.3f, 0));
    auto portal = [&](bool with_stencil) {
        softraster::Framebuffer fb(kSize, kSize);
        softraster::Context ctx(fb);
        ctx.clear(clear_color(kDark));
        ctx.state.cull = softraster::CullMode::None;
        if (with_stencil) {
            ctx.state.color_write = false;  // the mask only: no color,
            ctx.state.depth_write = false;  // no depth,
            ctx.state.stencil_test = true;  // stencil := 1 wherever the star is drawn
            ctx.state.stencil_front = ctx.state.stencil_back = {softraster::CompareFunc::Always, 1, 0xff, 0xff,
                                                                softraster::StencilOp::Keep, softraster::StencilOp::Keep, softraster::StencilOp::Replace};
            ctx.draw(softraster::Topology::Triangles, FlatShader{glm::mat4(1.0f), kCamera, glm::vec4(1.0f)}, std::span<const MeshIn>(star),
                     std::span<const uint32_t>(star_indices));
            ctx.state.color_write = true, ctx.state.depth_write = true;  // then the scene, only where stencil == 1
            ctx.state.stencil_front = ctx.state.stencil_back = {softraster::CompareFunc::Equal, 1, 0xff, 0xff,
                                                                softraster::StencilOp::Keep, softraster::StencilOp::Keep, softraster::StencilOp::Keep};
        }
        ctx.state.cull = softraster::CullMode::Back;
        ctx.draw(softraster::Topology::Triangles, LessonShader<Look::Stripes>{tilt, kCamera}, std::span<const MeshIn>(torus_vertices),
                 std::span<const uint32_t>(torus.indices));
        return to_canvas(ctx.read_pixels());
    };
    const Canvas whole = portal(false), cut = portal(true);
    beside({&whole, &cut}).save(out / "stencil.png", 2);
    wrote(out / "stencil.png");
    return 0;
}
