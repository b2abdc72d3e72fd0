// Lesson 6's test scene, also lesson 8's: a 4 x 4 grid of cubes on the ground, flat shaded
// (lesson 4) and culled, as screen triangles for lesson 5's z-buffer. `to_pixels` maps a
// clip-space corner to the screen (lesson 6's to_screen, or lesson 8's viewports).
#pragma once
#include <cmath>
#include <vector>

#include "../05-depth/depth.h"
#include "camera.h"
#include "softraster/scene/builtin_meshes.h"

namespace course {

template <class ToPixels>
std::vector<ScreenTriangle> cube_grid_triangles(const glm::mat4& view_projection, ToPixels to_pixels) {
    static const softraster::Mesh cube = softraster::make_cube(0.8);
    const Color colors[] = {kRed, kGreen, kBlue, kYellow};
    std::vector<ScreenTriangle> triangles;
    for (int gz = 0; gz < 4; ++gz)
        for (int gx = 0; gx < 4; ++gx) {
            const glm::vec3 at(-3.0f + 2.0f * float(gx), 0.0f, -3.0f + 2.0f * float(gz));  // 2 apart
            for (size_t t = 0; t + 2 < cube.indices.size(); t += 3) {
                glm::vec3 world[3];
                Point s[3];
                float z[3];
                for (int k = 0; k < 3; ++k) {
                    world[k] = cube.vertices[cube.indices[t + size_t(k)]].position + at;
                    const ScreenPoint p = to_pixels(view_projection * glm::vec4(world[k], 1.0f));
                    s[k] = {std::lround(p.x * kSub), std::lround(p.y * kSub)};
                    z[k] = p.depth;
                }
                if (edge_function(s[0], s[1], s[2]) >= 0) continue;  // lesson 4: seen from behind
                const glm::vec3 n = glm::normalize(glm::cross(world[1] - world[0], world[2] - world[0]));
                const float k = 0.25f + 0.75f * std::max(0.0f, glm::dot(n, glm::normalize(glm::vec3(0.5f, 1.0f, 0.7f))));
                const Color c = colors[(gx + gz) % 4];
                triangles.push_back({s[0], s[1], s[2], z[0], z[1], z[2], {uint8_t(c.r * k), uint8_t(c.g * k), uint8_t(c.b * k)}});
            }
        }
    return triangles;
}

}  // namespace course
