// A shaded triangle drawn through the library API alone: our own vertex type, our own
// varyings and our own shaders, no scene file. Writes triangle.png (or argv[1]).
//
//   build/example_triangle out.png
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "softraster/context.h"
#include "softraster/io/image_io.h"

struct Vertex {
    glm::vec3 position;
    glm::vec3 color;
};

struct Varyings {  // interpolated perspective-correctly across the triangle
    glm::vec3 color;
    glm::vec2 local;
};

struct GradientShader {
    using Vertex = ::Vertex;
    using Varyings = ::Varyings;
    glm::mat4 mvp;

    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.color = in.color;
        out.local = glm::vec2(in.position);
        return mvp * glm::vec4(in.position, 1.0f);
    }
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& color) const {
        // Vertex colors, darkened by rings around the triangle's center.
        const float ring = 0.75f + 0.25f * glm::cos(40.0f * glm::length(in.local));
        color = glm::vec4(in.color * ring, 1.0f);
        return true;
    }
};

int main(int argc, char** argv) {
    const char* out = argc > 1 ? argv[1] : "triangle.png";
    softraster::Framebuffer fb(480, 360, 4);
    softraster::Context ctx(fb);
    ctx.clear(glm::vec4(0.1f, 0.1f, 0.15f, 1.0f));
    ctx.state.cull = softraster::CullMode::None;

    const std::vector<Vertex> vertices = {
        {{-1.0f, -0.8f, 0.0f}, {1, 0, 0}}, {{1.0f, -0.8f, 0.0f}, {0, 1, 0}}, {{0.0f, 0.9f, 0.0f}, {0, 0, 1}}};
    const std::vector<uint32_t> indices = {0, 1, 2};
    const glm::mat4 proj = glm::perspective(glm::radians(45.0f), 480.0f / 360.0f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.6f, 0.3f, 2.6f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    ctx.draw(softraster::Topology::Triangles, GradientShader{proj * view}, std::span<const Vertex>(vertices),
             std::span<const uint32_t>(indices));

    softraster::write_png(ctx.read_pixels(), out);  // runs the recorded draws, then resolves
    std::printf("wrote %s\n", out);
    return 0;
}
