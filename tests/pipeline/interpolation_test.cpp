// Perspective-correct interpolation against the analytic answer: a tilted quad seen in
// perspective carries its world-space height as a varying; at every pixel center the
// interpolated value must equal the height where the eye ray through that center hits it.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

TEST(Interpolation, PerspectiveCorrectMatchesRayCast) {
    constexpr int W = 160, H = 120;
    const float fov = glm::radians(60.0f), aspect = float(W) / H;
    const glm::mat4 proj = glm::perspective(fov, aspect, 0.5f, 50.0f);
    // Quad from near (z = -1) to far (z = -9) rising in y: strong perspective foreshortening.
    const glm::vec3 p[4] = {{-2, -1, -1}, {2, -1, -1}, {2, 3, -9}, {-2, 3, -9}};
    std::vector<ClipVertexIn> v;
    for (const glm::vec3& q : p) v.push_back({proj * glm::vec4(q, 1.0f), q.y});
    std::vector<float> values(size_t(W) * H, NAN);
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    ctx.state.cull = CullMode::None;
    draw(ctx, CaptureShader{&values, W}, v, {0, 1, 2, 0, 2, 3});

    // Plane of the quad: points q with n . q = n . p0.
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[3] - p[0]));
    const float tan_half = std::tan(fov / 2);
    int checked = 0;
    float worst_affine_error = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float got = values[size_t(y) * W + size_t(x)];
            if (std::isnan(got)) continue;
            const glm::vec3 dir((2.0f * (x + 0.5f) / W - 1.0f) * tan_half * aspect, (1.0f - 2.0f * (y + 0.5f) / H) * tan_half, -1.0f);
            const float t = glm::dot(n, p[0]) / glm::dot(n, dir);
            const float expected = (t * dir).y;
            ASSERT_NEAR(got, expected, 2e-4f * (1.0f + std::fabs(expected))) << x << "," << y;
            // What screen-space (affine) interpolation would give along this column: linear in y.
            worst_affine_error = std::max(worst_affine_error, std::fabs(expected - (-1.0f + 4.0f * (1.0f - (y + 0.5f) / H))));
            ++checked;
        }
    EXPECT_GT(checked, 2000);
    EXPECT_GT(worst_affine_error, 0.5f);  // the test can tell perspective from affine interpolation
}

TEST(Interpolation, DepthIsAffineInWindowSpace) {
    constexpr int W = 64, H = 64;
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H, 0.1f), 0},
                                   {window_to_clip(128, 0, W, H, 0.9f), 0},
                                   {window_to_clip(0, 128, W, H, 0.5f), 0}};
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    draw(ctx, ConstantColorShader{}, v, {0, 2, 1});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float expected = 0.1f + 0.8f * (x + 0.5f) / 128 + 0.4f * (y + 0.5f) / 128;
            EXPECT_NEAR(fb.depth_data()[fb.sample_index(x, y)], expected, 1e-6f);
        }
}

// A varying with the same value at every corner is that value at every pixel, exactly, in
// perspective too: setup keeps the value instead of dividing a/w by 1/w (triangle_setup.h).
TEST(Interpolation, ConstantVaryingsAreExact) {
    constexpr int W = 97, H = 61;
    const glm::mat4 proj = glm::perspective(glm::radians(70.0f), float(W) / H, 0.3f, 40.0f);
    const float value = 0.7123f;  // (0.7123 * 1/w) / (1/w) rounds away from it at some pixels
    const glm::vec3 p[4] = {{-3, -1, -1}, {3, -1, -1}, {3, 4, -30}, {-3, 4, -30}};
    std::vector<ClipVertexIn> v;
    for (const glm::vec3& q : p) v.push_back({proj * glm::vec4(q, 1.0f), value});
    std::vector<float> values(size_t(W) * H, NAN);
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    ctx.state.cull = CullMode::None;
    draw(ctx, CaptureShader{&values, W}, v, {0, 1, 2, 0, 2, 3});
    int covered = 0;
    for (float got : values) {
        if (std::isnan(got)) continue;
        ASSERT_EQ(got, value);
        ++covered;
    }
    EXPECT_GT(covered, 1000);
}
