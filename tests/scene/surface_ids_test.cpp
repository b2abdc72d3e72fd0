// Surface ids and normals (surface_ids.h), seen from straight above by an orthographic
// camera, where every pixel's answer is known: two squares side by side, the right one
// nearer; a sphere, whose normal at a pixel's center is the direction from its center to
// the point there, up to its triangles' flatness.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "softraster/scene/scene.h"
#include "softraster/scene/surface_ids.h"

using namespace softraster;

namespace {

Scene scene_of(const std::string& objects) {
    return parse_scene(R"({"version": 2, "image": {"width": 40, "height": 20, "background": [0, 0, 0, 1]},
      "camera": {"projection": "orthographic", "eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "height": 2},
      "objects": [)" + objects + "]}",
                       ".", "surface_ids_test.json");
}

}  // namespace

// Pixel (px, py) sees x = -2 + (px + ½) / 10, z = -1 + (py + ½) / 10.
TEST(SurfaceIds, EachPixelNamesTheNearestTriangleAtItsCenter) {
    const Scene scene = scene_of(R"({"builtin": {"type": "plane", "size": 2}, "transform": {"translate": [-0.5, 0, 0]}},
                                    {"builtin": {"type": "plane", "size": 2}, "transform": {"translate": [1, 1, 0]}})");
    const SurfaceIds ids = surface_ids(scene, 2);
    ASSERT_EQ(ids.object.size(), 800u);
    for (int py = 0; py < 20; ++py)
        for (int px = 0; px < 40; ++px) {
            const double x = -2 + (px + 0.5) / 10;
            const int want = x > 0 ? 1 : x > -1.5 ? 0 : -1;  // the right square covers x in [0, 2], nearer
            const size_t p = size_t(py) * 40 + size_t(px);
            ASSERT_EQ(ids.object[p], want) << px << ", " << py;
            if (want < 0) EXPECT_EQ(ids.triangle[p], -1);
            else EXPECT_TRUE(ids.triangle[p] == 0 || ids.triangle[p] == 1) << ids.triangle[p];
        }
    // The plane's two triangles split it along a diagonal: both appear.
    EXPECT_NE(ids.triangle[10 * 40 + 21], ids.triangle[10 * 40 + 38]);
}

TEST(SurfaceIds, NormalsAreTheSurfacesAtThePixelCenters) {
    const Scene scene = scene_of(R"({"builtin": {"type": "uv_sphere", "radius": 0.9}, "material": {"shading": "lambert"}},
                                    {"builtin": {"type": "plane", "size": 2}, "transform": {"translate": [1.5, 0, 0], "rotate": [0, 0, 30]},
                                     "material": {"shading": "flat"}})");
    const SurfaceIds ids = surface_ids(scene, 1);
    const std::vector<glm::vec3> world = surface_normals(scene, ids, NormalSpace::World);
    const std::vector<glm::vec3> camera = surface_normals(scene, ids, NormalSpace::Camera);
    int sphere = 0, plane = 0;
    for (int py = 0; py < 20; ++py)
        for (int px = 0; px < 40; ++px) {
            const size_t p = size_t(py) * 40 + size_t(px);
            const glm::vec3 n = world[p];
            if (ids.object[p] < 0) {
                EXPECT_EQ(n, glm::vec3(0.0f));
                continue;
            }
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
            // Camera: x right (world +x), y down (world +z, the picture's top being -z), z forward (world -y).
            EXPECT_NEAR(camera[p].x, n.x, 1e-5f);
            EXPECT_NEAR(camera[p].y, n.z, 1e-5f);
            EXPECT_NEAR(camera[p].z, -n.y, 1e-5f);
            const float x = -2.0f + (px + 0.5f) / 10.0f, z = -1.0f + (py + 0.5f) / 10.0f;
            if (ids.object[p] == 0) {  // the sphere's point under the pixel, up to flat facets
                const glm::vec3 on_sphere(x, std::sqrt(std::max(0.0f, 0.81f - x * x - z * z)), z);
                if (glm::length(glm::vec2(x, z)) < 0.8f) {
                    EXPECT_GT(glm::dot(n, glm::normalize(on_sphere)), 0.999f) << px << ", " << py;
                }
                ++sphere;
            } else {  // the plane's face normal: +y turned 30 degrees about z
                EXPECT_NEAR(n.x, -0.5f, 1e-5f);
                EXPECT_NEAR(n.y, std::sqrt(3.0f) / 2.0f, 1e-5f);
                ++plane;
            }
        }
    EXPECT_GT(sphere, 150);
    EXPECT_GT(plane, 100);
}
