// Lesson 11 (course/11-lighting): the lesson's diffuse, Phong and Blinn-Phong terms are the
// production shaders' (include/softraster/shading/lighting.h) on random directions, and the
// two highlights peak where they should: Phong's where the mirror direction meets the eye,
// Blinn's where the normal meets the half vector (the same place).
#include <gtest/gtest.h>

#include <random>

#include "course/11-lighting/lighting.h"
#include "softraster/shading/lighting.h"

using namespace course;

TEST(CourseLighting, TheLessonsTermsAreTheProductionShaders) {
    std::mt19937 rng(16);
    std::normal_distribution<float> g(0.0f, 1.0f);
    auto unit = [&] { return glm::normalize(glm::vec3(g(rng), g(rng), g(rng))); };
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 n = unit(), l = unit(), v = unit();
        for (float s : {1.0f, 8.0f, 24.0f, 96.0f}) {
            const float nl = glm::dot(n, l);
            EXPECT_NEAR(specular_phong(n, l, v, s), softraster::specular_factor<softraster::Specular::Phong>(n, l, v, nl, s), 1e-4f);
            EXPECT_NEAR(specular_blinn_phong(n, l, v, s), softraster::specular_factor<softraster::Specular::BlinnPhong>(n, l, v, nl, s), 1e-4f);  // (pow against repeated squaring)
        }
        EXPECT_EQ(diffuse(n, l), std::max(0.0f, glm::dot(n, l)));
    }
}

TEST(CourseLighting, HighlightsPeakAtTheMirrorDirection) {
    const glm::vec3 n(0, 1, 0), l = glm::normalize(glm::vec3(1, 1, 0)), mirror = glm::normalize(glm::vec3(-1, 1, 0));
    EXPECT_NEAR(specular_phong(n, l, mirror, 50.0f), 1.0f, 1e-5f);
    EXPECT_NEAR(specular_blinn_phong(n, l, mirror, 50.0f), 1.0f, 1e-5f);
    const glm::vec3 off = glm::normalize(glm::vec3(-1, 1.2f, 0.3f));
    EXPECT_LT(specular_phong(n, l, off, 50.0f), 0.5f);
    EXPECT_LT(specular_blinn_phong(n, l, off, 50.0f), specular_blinn_phong(n, l, mirror, 50.0f));
    EXPECT_EQ(specular_phong(n, l, -mirror, 50.0f), 0.0f);  // the eye below the surface: nothing
}
