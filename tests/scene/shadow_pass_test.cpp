// Shadow maps through the scene renderer: a cube over a floor, lit from the upper right and
// seen from straight above. Properties that hold whatever the map's texels: the floor deep
// in the cube's shadow is exactly as if the light were black, the floor far from it exactly
// as without the shadow, and a shadow never brightens a pixel.
#include <gtest/gtest.h>

#include <string>

#include "softraster/scene/scene.h"
#include "softraster/scene/scene_renderer.h"
#include "test_support.h"

using namespace softraster;

namespace {

Image render_json(const std::string& shading, const std::string& light_color, const std::string& shadow) {
    const std::string json = R"({"version": 2, "image": {"width": 64, "height": 64, "background": [0, 0, 0, 1]},
      "camera": {"projection": "orthographic", "eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "height": 4},
      "lights": {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [-1, -1, 0], "color": )" + light_color + shadow + R"(}]},
      "objects": [{"builtin": {"type": "plane", "size": 4}, "material": {"shading": ")" + shading + R"(", "specular": [0.5, 0.5, 0.5]}},
                  {"builtin": {"type": "cube", "size": 1}, "transform": {"translate": [1, 1.5, 0]},
                   "material": {"shading": ")" + shading + R"(", "color": [0, 0, 1, 1]}}]})";
    // A file per test: ctest runs the tests of this file in parallel processes.
    const std::string name = std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json";
    return SceneRenderer(load_scene(test::write_temp_file("softraster_shadow_tests", name, json)), 2).render();
}

}  // namespace

TEST(ShadowPass, ShadowIsTheLightsAbsenceAndNothingElse) {
    for (const char* shading : {"lambert", "flat", "blinn_phong", "phong", "pbr"}) {
        SCOPED_TRACE(shading);
        const Image lit = render_json(shading, "[0.6, 0.6, 0.6]", "");
        const Image dark = render_json(shading, "[0, 0, 0]", "");
        const Image shadowed = render_json(shading, "[0.6, 0.6, 0.6]", R"(, "shadow": {"size": 256})");
        // Pixel (px, py) sees the floor at x = -2 + (px + ½)/16, z = -2 + (py + ½)/16. The cube
        // (x in [0.5, 1.5], y in [1, 2], |z| ≤ 0.5) shades the floor over x in [-1.5, 0.5], |z| < 0.5.
        int in_shadow = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const Rgba8 a = lit.at(x, y), b = shadowed.at(x, y);
                ASSERT_TRUE(b.r <= a.r && b.g <= a.g && b.b <= a.b) << x << ", " << y;
                if (x >= 14 && x <= 34 && y >= 28 && y <= 36) {
                    EXPECT_EQ(b, dark.at(x, y)) << x << ", " << y;
                    in_shadow += b != a;
                }
                if (y >= 48) {
                    EXPECT_EQ(b, a) << x << ", " << y;
                }
            }
        EXPECT_EQ(in_shadow, 21 * 9);
    }
}

// Gouraud lights at the vertices, where there is no shadow map to read: a shadow changes
// nothing. The light does reach the picture (so both are not simply empty): a black light
// gives another one, and the floor and the blue cube are drawn.
TEST(ShadowPass, GouraudIsNotShadowed) {
    const Image shadowed = render_json("gouraud", "[0.6, 0.6, 0.6]", R"(, "shadow": {})");
    EXPECT_EQ(shadowed.pixels, render_json("gouraud", "[0.6, 0.6, 0.6]", "").pixels);
    EXPECT_NE(shadowed.pixels, render_json("gouraud", "[0, 0, 0]", R"(, "shadow": {})").pixels);
    int floor = 0, cube = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Rgba8 c = shadowed.at(x, y);
            floor += c.r > 0 && c.r == c.g && c.g == c.b;  // the white floor, gray under the light
            cube += c.b > 0 && c.r == 0 && c.g == 0;       // the blue cube
        }
    EXPECT_GT(floor, 64 * 64 / 2);
    EXPECT_GT(cube, 100);
}

namespace {

// A point light at (0, 3, 0) over a 10 x 10 floor, seen from straight above (pixel (px, py)
// sees x = -5 + (px + ½) 10/64, z likewise from py): a cube of side 1 at (0, 1.5, 0) right
// under it, and one at (2.5, 0.5, 0) to its side.
Image render_point(const std::string& light_color, const std::string& shadow) {
    const std::string json = R"({"version": 2, "image": {"width": 64, "height": 64, "background": [0, 0, 0, 1]},
      "camera": {"projection": "orthographic", "eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "height": 10},
      "lights": {"ambient": [0.2, 0.2, 0.2], "point": [{"position": [0, 3, 0], "intensity": 9, "color": )" + light_color + shadow + R"(}]},
      "objects": [{"builtin": {"type": "plane", "size": 10, "divisions": 8}, "material": {"shading": "lambert"}},
                  {"builtin": {"type": "cube", "size": 1}, "transform": {"translate": [0, 1.5, 0]}, "material": {"shading": "lambert"}},
                  {"builtin": {"type": "cube", "size": 1}, "transform": {"translate": [2.5, 0.5, 0]}, "material": {"shading": "lambert"}}]})";
    const std::string name = std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + light_color.substr(1, 1) +
                             std::to_string(shadow.size()) + ".json";
    return SceneRenderer(load_scene(test::write_temp_file("softraster_shadow_tests", name, json)), 2).render();
}

}  // namespace

// A point light's cube: the floor around the cube below the light lies in the cube's -y face,
// the floor beyond the side cube in its +x face; both are dark as without the light, the far
// side of the floor (the -x face, no caster) as without the shadow.
TEST(ShadowPass, APointLightsCubeShadowsEveryDirection) {
    const Image lit = render_point("[1, 1, 1]", "");
    const Image dark = render_point("[0, 0, 0]", "");
    const Image shadowed = render_point("[1, 1, 1]", R"(, "shadow": {"size": 512})");
    auto floor_x = [](int p) { return -5.0f + (float(p) + 0.5f) * 10.0f / 64.0f; };
    int below = 0, beside = 0, far = 0;
    for (int py = 0; py < 64; ++py)
        for (int px = 0; px < 64; ++px) {
            const Rgba8 a = lit.at(px, py), b = shadowed.at(px, py);
            ASSERT_TRUE(b.r <= a.r && b.g <= a.g && b.b <= a.b) << px << ", " << py;
            const float x = floor_x(px), z = floor_x(py), ring = std::max(std::abs(x), std::abs(z));
            const bool in_shadow = (ring > 0.6f && ring < 1.1f) || (x > 3.2f && x < 4.2f && std::abs(z) < 0.3f);
            if (in_shadow) {
                EXPECT_EQ(b, dark.at(px, py)) << px << ", " << py;
                EXPECT_NE(b, a) << px << ", " << py;
                (ring < 1.1f ? below : beside) += 1;
            }
            if (x < -3.0f) {
                EXPECT_EQ(b, a) << px << ", " << py;
                ++far;
            }
        }
    EXPECT_GT(below, 80);
    EXPECT_GT(beside, 10);
    EXPECT_GT(far, 500);
}
