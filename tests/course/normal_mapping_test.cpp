// Lesson 16 (course/16-normal-mapping): the lesson's tangent-space normal is the production
// shaders' (include/softraster/shading/normal_mapping.h) on random frames and texels; a flat
// texel leaves the surface's normal as it is, and the map's normals tilt towards +u and +v
// as the tangent and bitangent say.
#include <gtest/gtest.h>

#include <random>

#include "course/16-normal-mapping/normal_map.h"
#include "softraster/shading/normal_mapping.h"

using namespace course;

TEST(CourseNormalMapping, TheLessonsNormalIsTheProductionShaders) {
    std::mt19937 rng(22);
    std::normal_distribution<float> g(0.0f, 1.0f);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int n = 0; n < 20000; ++n) {
        const glm::vec3 N = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        const glm::vec3 T = glm::normalize(glm::cross(N, glm::vec3(g(rng), g(rng), g(rng))));
        const glm::vec4 tangent(T, n % 2 ? 1.0f : -1.0f);
        const glm::vec3 texel(u(rng), u(rng), 0.5f + 0.5f * u(rng));
        const glm::vec3 ours = perturbed_normal(N, tangent, texel), theirs = softraster::mapped_normal(N, tangent, texel, 1.0f);
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(ours[k], theirs[k], 1e-6f) << n;
    }
    const glm::vec3 N(0, 0, 1);
    const glm::vec4 T(1, 0, 0, 1);
    const glm::vec3 flat = perturbed_normal(N, T, {0.5f, 0.5f, 1.0f});
    EXPECT_NEAR(glm::distance(flat, N), 0.0f, 1e-6f);
    EXPECT_GT(perturbed_normal(N, T, {0.8f, 0.5f, 0.9f}).x, 0.1f);   // +x in the map: towards the tangent
    EXPECT_GT(perturbed_normal(N, T, {0.5f, 0.8f, 0.9f}).y, 0.1f);   // +y: towards B = cross(N, T) = +y
    EXPECT_LT(perturbed_normal(N, {1, 0, 0, -1}, {0.5f, 0.8f, 0.9f}).y, -0.1f);  // w = -1: the texture glued mirrored
}
