// Lesson 7: clipping. A floor that reaches behind the camera, drawn without and with
// clipping at the near plane; and lines cut to a window by Cohen-Sutherland.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "../01-lines/lines.h"
#include "../05-depth/depth.h"
#include "../06-camera/camera.h"
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "clip.h"

using namespace course;

namespace {

constexpr int kW = 200, kH = 150;

Color to_color(const glm::vec3& c) { return {uint8_t(255.0f * c.r), uint8_t(255.0f * c.g), uint8_t(255.0f * c.b)}; }

// A floor of 4 x 6 big tiles from z = +6 (behind the camera, which stands at z = 3) to
// z = -18, in checker colors; each tile two triangles.
std::vector<std::array<ClipCorner, 3>> floor_triangles(const glm::mat4& view_projection) {
    std::vector<std::array<ClipCorner, 3>> out;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 4; ++i) {
            const glm::vec3 color = (i + j) % 2 ? glm::vec3(0.85f, 0.8f, 0.3f) : glm::vec3(0.25f, 0.45f, 0.8f);
            const float x0 = -8.0f + 4.0f * float(i), z0 = 6.0f - 4.0f * float(j);
            auto corner = [&](float x, float z) { return ClipCorner{view_projection * glm::vec4(x, -1.0f, z, 1.0f), color}; };
            const ClipCorner a = corner(x0, z0), b = corner(x0 + 4, z0), c = corner(x0 + 4, z0 - 4), d = corner(x0, z0 - 4);
            out.push_back({a, b, c});
            out.push_back({a, c, d});
        }
    return out;
}

ScreenTriangle on_screen(const ClipCorner& a, const ClipCorner& b, const ClipCorner& c) {
    const ScreenPoint p[3] = {to_screen(a.position, kW, kH), to_screen(b.position, kW, kH), to_screen(c.position, kW, kH)};
    auto fixed = [](const ScreenPoint& q) {  // (far outside points kept in range for the integers)
        return Point{std::lround(std::clamp(q.x, -1e5f, 1e5f) * kSub), std::lround(std::clamp(q.y, -1e5f, 1e5f) * kSub)};
    };
    return {fixed(p[0]), fixed(p[1]), fixed(p[2]), p[0].depth, p[1].depth, p[2].depth, to_color(a.color)};
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    const glm::mat4 vp = perspective(60.0f, float(kW) / float(kH), 0.5f, 40.0f) * look_at({0, 0.5f, 3}, {0, -0.5f, -4}, {0, 1, 0});
    std::vector<ScreenTriangle> unclipped, clipped;
    for (const auto& t : floor_triangles(vp)) {
        unclipped.push_back(on_screen(t[0], t[1], t[2]));  // divided by w whatever its sign
        const std::vector<ClipCorner> polygon = clip_to_frustum({t[0], t[1], t[2]});
        for (size_t k = 1; k + 1 < polygon.size(); ++k) clipped.push_back(on_screen(polygon[0], polygon[k], polygon[k + 1]));  // a fan
    }
    Canvas without(kW, kH), with(kW, kH);
    draw_painter(unclipped, without);  // (depth is meaningless for corners behind the camera)
    draw_z_buffer(clipped, with);
    beside({&without, &with}).save(out / "near_plane.png", 2);
    wrote(out / "near_plane.png");

    // Cohen-Sutherland: 40 random segments against the middle window; the kept parts bright,
    // the rest dim, the window's border gray.
    constexpr int kSize = 160;
    Canvas lines(kSize, kSize);
    const glm::vec2 lo(40.0f, 50.0f), hi(120.0f, 110.0f);
    for (int x = 40; x <= 120; ++x) lines.set(x, 50, kGray), lines.set(x, 110, kGray);
    for (int y = 50; y <= 110; ++y) lines.set(40, y, kGray), lines.set(120, y, kGray);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(0.0f, float(kSize - 1));
    for (int n = 0; n < 40; ++n) {
        Segment2 s{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        auto draw = [&](const Segment2& seg, Color c) {
            line_bresenham(int(std::lround(seg.a.x)), int(std::lround(seg.a.y)), int(std::lround(seg.b.x)), int(std::lround(seg.b.y)),
                           [&](int x, int y) { lines.set(x, y, c); });
        };
        draw(s, Color{70, 70, 80});
        if (clip_cohen_sutherland(s, lo, hi)) draw(s, kYellow);
    }
    lines.save(out / "cohen_sutherland.png", 2);
    wrote(out / "cohen_sutherland.png");
    return 0;
}
