// Lesson 8: NDC and the viewport. One picture, four viewports, four cameras (a CAD program's
// quad view): front, top and side orthographic, and a perspective view; then the same
// perspective view with the wrong aspect ratio.
#include "../05-depth/depth.h"
#include "../06-camera/cube_grid.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "viewport.h"

using namespace course;

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    constexpr int kW = 320, kH = 240;
    const float half_w = kW / 2.0f, half_h = kH / 2.0f, aspect = half_w / half_h;
    struct View {
        ViewportRect rect;
        glm::mat4 view_projection;
    };
    const glm::mat4 ortho = orthographic(4.0f * aspect, 4.0f, 0.1f, 50.0f);
    const View views[] = {
        {{0, 0, half_w, half_h}, ortho * look_at({0, 0, 20}, {0, 0, 0}, {0, 1, 0})},                // front
        {{half_w, 0, half_w, half_h}, ortho * look_at({0, 20, 0}, {0, 0, 0}, {0, 0, -1})},          // top
        {{0, half_h, half_w, half_h}, ortho * look_at({20, 0, 0}, {0, 0, 0}, {0, 1, 0})},           // side
        {{half_w, half_h, half_w, half_h}, perspective(45.0f, aspect, 0.1f, 50.0f) * look_at({6, 5, 9}, {0, 0, 0}, {0, 1, 0})},
    };
    // Every viewport's triangles into one picture with one z-buffer: the viewports do not
    // overlap, so neither do their pixels (a GPU does the same with one depth buffer).
    std::vector<ScreenTriangle> all;
    for (const View& v : views) {
        const auto triangles = cube_grid_triangles(v.view_projection, [&](const glm::vec4& clip) { return to_viewport(clip, v.rect); });
        all.insert(all.end(), triangles.begin(), triangles.end());
    }
    Canvas quad(kW, kH);
    draw_z_buffer(all, quad);
    for (int x = 0; x < kW; ++x) quad.set(x, kH / 2, kGray);
    for (int y = 0; y < kH; ++y) quad.set(kW / 2, y, kGray);
    quad.save(out / "quad_view.png", 2);
    wrote(out / "quad_view.png");

    // The projection's aspect ratio must be the viewport's: a square projection (aspect 1)
    // in a wide viewport stretches everything sideways.
    const ViewportRect wide{0, 0, 240, 120};
    Canvas right(240, 120), wrong(240, 120);
    const glm::mat4 camera = look_at({6, 5, 9}, {0, 0, 0}, {0, 1, 0});
    draw_z_buffer(cube_grid_triangles(perspective(45.0f, 2.0f, 0.1f, 50.0f) * camera, [&](const glm::vec4& c) { return to_viewport(c, wide); }), right);
    draw_z_buffer(cube_grid_triangles(perspective(45.0f, 1.0f, 0.1f, 50.0f) * camera, [&](const glm::vec4& c) { return to_viewport(c, wide); }), wrong);
    beside({&right, &wrong}).save(out / "aspect.png", 2);
    wrote(out / "aspect.png");
    return 0;
}
