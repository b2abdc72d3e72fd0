// Lesson 6 (course/06-camera): the lesson's lookAt, perspective and orthographic matrices
// are the ones the production scene renderer uses (view_matrix and projection_matrix in
// src/scene/transforms.cpp, OpenGL's gluLookAt, gluPerspective and glOrtho) for random
// cameras; and a point straight ahead lands in the middle of the screen at the depth the
// derivation says.
#include <gtest/gtest.h>

#include <random>

#include "course/06-camera/camera.h"
#include "softraster/scene/scene.h"

using namespace course;

namespace {

void expect_near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance * std::max(1.0f, std::fabs(b[c][r]))) << "[" << c << "][" << r << "]";
}

}  // namespace

TEST(CourseCamera, TheLessonsMatricesAreThePipelines) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> coord(-10.0f, 10.0f), fov(10.0f, 120.0f), near(0.05f, 2.0f);
    for (int n = 0; n < 500; ++n) {
        softraster::Camera cam;
        cam.eye = {coord(rng), coord(rng), coord(rng)};
        cam.target = {coord(rng), coord(rng), coord(rng)};
        if (glm::length(cam.target - cam.eye) < 1.0f) continue;
        cam.up = glm::normalize(glm::vec3(coord(rng), coord(rng), coord(rng)));
        if (glm::length(glm::cross(glm::normalize(cam.target - cam.eye), cam.up)) < 0.1f) continue;
        cam.fov_y = fov(rng);
        cam.near = near(rng);
        cam.far = cam.near * 50.0f;
        expect_near(look_at(cam.eye, cam.target, cam.up), softraster::view_matrix(cam), 1e-5f);
        expect_near(perspective(cam.fov_y, 640.0f / 480.0f, cam.near, cam.far), softraster::projection_matrix(cam, 640, 480), 1e-5f);
        cam.orthographic = true;
        cam.height = near(rng) * 5.0f;
        expect_near(orthographic(cam.height / 2.0f * 640.0f / 480.0f, cam.height / 2.0f, cam.near, cam.far),
                    softraster::projection_matrix(cam, 640, 480), 1e-5f);
    }
}

TEST(CourseCamera, StraightAheadIsTheMiddleAndDepthFollowsTheDerivation) {
    const glm::mat4 view = look_at({1, 2, 3}, {1, 2, -7}, {0, 1, 0});
    const glm::mat4 proj = perspective(60.0f, 2.0f, 1.0f, 11.0f);
    for (float d : {1.0f, 2.0f, 6.0f, 11.0f}) {
        const ScreenPoint p = to_screen(proj * view * glm::vec4(1, 2, 3 - d, 1), 200, 100);
        EXPECT_NEAR(p.x, 100.0f, 1e-4f);
        EXPECT_NEAR(p.y, 50.0f, 1e-4f);
        // z_ndc = (f + n)/(f - n) - 2 f n / ((f - n) d): -1 at the near plane, +1 at the far one.
        const float ndc = (11.0f + 1.0f) / 10.0f - 2.0f * 11.0f * 1.0f / (10.0f * d);
        EXPECT_NEAR(p.depth, (ndc + 1.0f) / 2.0f, 1e-6f) << d;
    }
}
