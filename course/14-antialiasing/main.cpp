// Lesson 14: supersampling against multisampling. Thin spokes (edge aliasing) and a fine
// checkerboard floor (shading aliasing), each with one sample per pixel, 2 x 2 supersampling
// and 4x multisampling, on the real pipeline; the time each takes at 800 x 600 is printed.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "../common/pipeline.h"
#include "softraster/pipeline/resolve.h"

using namespace course;

namespace {

enum class Aa { None, Ssaa, Msaa };

// A checkerboard computed per pixel from the world position: its squares shrink to less
// than a pixel towards the horizon, where only more shading (SSAA) can average them.
struct FloorVertex {
    glm::vec3 position;
};
struct FloorVaryings {
    glm::vec2 ground;
};
struct FloorShader {
    using Vertex = FloorVertex;
    using Varyings = FloorVaryings;
    glm::mat4 view_projection;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.ground = {in.position.x, in.position.z};
        return view_projection * glm::vec4(in.position, 1.0f);
    }
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& c) const {
        const bool dark = (int(std::floor(in.ground.x * 2.0f)) + int(std::floor(in.ground.y * 2.0f))) % 2 != 0;
        c = dark ? glm::vec4(0.16f, 0.31f, 0.67f, 1.0f) : glm::vec4(0.94f, 0.94f, 0.92f, 1.0f);
        return true;
    }
};

// Draws the scene at width x height with the given anti-aliasing: supersampling draws at
// twice the size and averages each 2 x 2 block (downsample_box); multisampling keeps 4
// samples per pixel and averages them at the end (resolve).
template <class Draw>
softraster::Image render(int width, int height, Aa aa, Draw draw) {
    const int k = aa == Aa::Ssaa ? 2 : 1;
    softraster::Framebuffer fb(width * k, height * k, aa == Aa::Msaa ? 4 : 1);
    softraster::Context ctx(fb);
    ctx.clear(clear_color(kDark));
    ctx.state.cull = softraster::CullMode::None;
    draw(ctx, float(width * k), float(height * k));
    const softraster::Image picture = ctx.read_pixels();  // (MSAA: resolved here)
    return k == 1 ? picture : softraster::downsample_box(picture, k);
}

void spokes(softraster::Context& ctx, float w, float h) {
    std::vector<PixelVertex> v;
    const float cx = w / 2, cy = h / 2, s = w / 80.0f;  // s: pixels of the 80-pixel picture
    for (int k = 0; k < 24; ++k) {
        const float a = glm::radians(15.0f * float(k)), da = glm::radians(1.2f);
        v.push_back({{cx, cy}});
        v.push_back({{cx + 38 * s * std::cos(a), cy + 38 * s * std::sin(a)}});
        v.push_back({{cx + 38 * s * std::cos(a + da), cy + 38 * s * std::sin(a + da)}});
    }
    std::vector<uint32_t> indices(v.size());
    for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
    ctx.draw(softraster::Topology::Triangles, PixelShader{w, h}, std::span<const PixelVertex>(v), std::span<const uint32_t>(indices));
    ctx.finish();  // (a recorded draw reads its vertices when it runs: before they go)
}

void checker_floor(softraster::Context& ctx, float w, float h) {
    const std::vector<FloorVertex> v = {{{-40, 0, 2}}, {{40, 0, 2}}, {{40, 0, -80}}, {{-40, 0, -80}}};
    const uint32_t indices[] = {0, 1, 2, 0, 2, 3};
    const glm::mat4 camera = perspective(60.0f, w / h, 0.1f, 200.0f) * look_at({0, 1, 2}, {0, 0.3f, -4}, {0, 1, 0});
    ctx.draw(softraster::Topology::Triangles, FloorShader{camera}, std::span<const FloorVertex>(v), std::span<const uint32_t>(indices));
    ctx.finish();
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const Canvas e1 = to_canvas(render(80, 80, Aa::None, spokes)), e2 = to_canvas(render(80, 80, Aa::Ssaa, spokes)),
                 e4 = to_canvas(render(80, 80, Aa::Msaa, spokes));
    beside({&e1, &e2, &e4}).save(out / "edges.png", 4);
    wrote(out / "edges.png");
    const Canvas f1 = to_canvas(render(160, 90, Aa::None, checker_floor)), f2 = to_canvas(render(160, 90, Aa::Ssaa, checker_floor)),
                 f4 = to_canvas(render(160, 90, Aa::Msaa, checker_floor));
    beside({&f1, &f2, &f4}).save(out / "shading.png", 2);
    wrote(out / "shading.png");
    // The cost, at 800 x 600 (the best of 5 runs each; not part of the pictures).
    for (const auto& [name, aa] : {std::pair{"no anti-aliasing", Aa::None}, std::pair{"SSAA 2x2", Aa::Ssaa}, std::pair{"MSAA 4x", Aa::Msaa}}) {
        double best = 1e9;
        for (int run = 0; run < 5; ++run) {
            const auto start = std::chrono::steady_clock::now();
            render(800, 600, aa, checker_floor);
            best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::printf("%-18s %7.2f ms (the floor at 800 x 600, one thread)\n", name, best);
    }
    return 0;
}
