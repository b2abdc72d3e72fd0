// Lesson 4 (course/04-flat-shading): back-face culling by the sign of the screen-space area
// agrees with the normal's direction (for a view along -z) and with the production
// pipeline's culling (include/softraster/pipeline/culling.h); Lambert's law on known angles.
#include <gtest/gtest.h>

#include <random>

#include "course/04-flat-shading/shade.h"
#include "course/common/pipeline.h"

using namespace course;

TEST(CourseFlatShading, LambertIsTheCosineOfTheAngle) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);  // normal +z
    EXPECT_FLOAT_EQ(lambert(a, b, c, {0, 0, 1}), 1.0f);
    EXPECT_NEAR(lambert(a, b, c, {0, 1, 1}), std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(lambert(a, b, c, {0, 0, -1}), 0.0f);  // lit from behind
    EXPECT_EQ(lambert(a, c, b, {0, 0, 1}), 0.0f);   // the other winding: the normal is -z
}

TEST(CourseFlatShading, CullingOnTheScreenAgreesWithTheNormalAndThePipeline) {
    constexpr int kSize = 64;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> coord(-1.0f, 1.0f);
    int culled = 0, kept = 0;
    for (int n = 0; n < 2000; ++n) {
        glm::vec3 p[3];
        for (glm::vec3& v : p) v = {coord(rng), coord(rng), coord(rng)};
        // Lesson 2's projection: drop z; x right, y down on the screen.
        Point s[3];
        for (int k = 0; k < 3; ++k) s[k] = {int64_t(std::lround((p[k].x + 1.0f) * 0.5f * kSize * kSub)), int64_t(std::lround((1.0f - p[k].y) * 0.5f * kSize * kSub))};
        const int64_t area = edge_function(s[0], s[1], s[2]);
        if (std::abs(area) < 256 * 256) continue;  // (nearly edge-on: snapping may flip the sign)
        const bool away = faces_away_on_screen(s[0], s[1], s[2]);
        ASSERT_EQ(away, faces_away_in_3d(p[0], p[1], p[2])) << n;
        const PixelVertex v[3] = {{{float(s[0].x) / kSub, float(s[0].y) / kSub}}, {{float(s[1].x) / kSub, float(s[1].y) / kSub}},
                                  {{float(s[2].x) / kSub, float(s[2].y) / kSub}}};
        const auto all = pipeline_coverage(kSize, kSize, softraster::Topology::Triangles, v);
        const auto back_culled = pipeline_coverage(kSize, kSize, softraster::Topology::Triangles, v, softraster::CullMode::Back);
        if (away) {
            ASSERT_EQ(std::count(back_culled.begin(), back_culled.end(), true), 0) << n;
            ++culled;
        } else {
            ASSERT_EQ(back_culled, all) << n;
            ++kept;
        }
    }
    EXPECT_GT(culled, 500);
    EXPECT_GT(kept, 500);
}
