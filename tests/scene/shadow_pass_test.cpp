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

TEST(ShadowPass, GouraudIsNotShadowed) {
    EXPECT_EQ(render_json("gouraud", "[0.6, 0.6, 0.6]", R"(, "shadow": {})").pixels,
              render_json("gouraud", "[0.6, 0.6, 0.6]", "").pixels);
}
