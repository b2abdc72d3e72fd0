// Lesson 15 (course/15-shadows): the shadow map's answer equals the geometric one. A ball
// over a floor under a directional light; a floor point is in shadow exactly when the ray
// from it towards the light meets the ball, checked away from the shadow's edge (where the
// map's texels decide), with the lesson's bias.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "course/06-camera/camera.h"
#include "course/15-shadows/shadow.h"
#include "softraster/scene/builtin_meshes.h"

using namespace course;

TEST(CourseShadows, TheMapAgreesWithTheRayToTheLight) {
    const softraster::Mesh floor = softraster::make_plane(6.0, 1), ball = softraster::make_uv_sphere(0.5, 48, 96);
    const std::vector<MeshIn> fv = mesh_vertices(floor), bv = mesh_vertices(ball);
    const glm::vec3 center(0.3f, 0.9f, -0.2f);
    const std::vector<Placed> scene = {{&fv, &floor.indices, glm::mat4(1.0f)}, {&bv, &ball.indices, glm::translate(glm::mat4(1.0f), center)}};
    const glm::vec3 to_light = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f));
    const ShadowMap map = render_shadow_map(scene, orthographic(3.5f, 3.5f, 0.1f, 20.0f) * look_at(to_light * 8.0f, {0, 0, 0}, {0, 1, 0}), 512);
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> coord(-2.5f, 2.5f);
    int shadowed = 0, lit = 0;
    for (int n = 0; n < 20000; ++n) {
        const glm::vec3 p(coord(rng), 0.0f, coord(rng));
        // The ray p + t to_light against the ball: its distance from the center.
        const glm::vec3 d = center - p;
        const float t = glm::dot(d, to_light), miss = glm::length(d - t * to_light);
        // (The ball is 48 x 96 facets: its outline lies within 0.5 (1 - cos(pi / 48)) of the sphere.)
        if (std::fabs(miss - 0.5f) < 0.05f) continue;  // near the shadow's edge: the map's texels (7/512) and facets decide
        const bool geometric = t > 0.0f && miss < 0.5f;
        ASSERT_EQ(in_shadow(map, p, 0.004f), geometric) << p.x << "," << p.z;
        (geometric ? shadowed : lit)++;
    }
    EXPECT_GT(shadowed, 300);
    EXPECT_GT(lit, 10000);
}
