// Lesson 10 (course/10-shaders): a varying the vertex shader writes reaches each pixel's
// fragment shader as lesson 9's perspective-correct interpolation of the corners' values;
// the picture's 8-bit colors are those values, rounded.
#include <gtest/gtest.h>

#include <random>

#include "course/06-camera/camera.h"
#include "course/09-interpolation/interpolate.h"
#include "course/10-shaders/shaders.h"

using namespace course;

TEST(CourseShaders, VaryingsArriveInterpolatedPerspectiveCorrectly) {
    constexpr int kSize = 64;
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> coord(-1.0f, 1.0f), depth(-3.0f, 0.5f), channel(0.0f, 1.0f);
    const glm::mat4 camera = perspective(50.0f, 1.0f, 0.1f, 20.0f) * look_at({0, 0, 2.5f}, {0, 0, 0}, {0, 1, 0});
    size_t pixels = 0;
    for (int n = 0; n < 100; ++n) {
        std::vector<MeshIn> v(3);
        for (MeshIn& c : v) c = {{coord(rng), coord(rng), depth(rng)}, {0, 0, 1}, {channel(rng), channel(rng), channel(rng), 1.0f}};
        softraster::Framebuffer fb(kSize, kSize);
        softraster::Context ctx(fb);
        ctx.state.cull = softraster::CullMode::None;
        const uint32_t indices[] = {0, 1, 2};
        ctx.draw(softraster::Topology::Triangles, LessonShader<Look::VertexColor>{glm::mat4(1.0f), camera}, std::span<const MeshIn>(v),
                 std::span<const uint32_t>(indices));
        const softraster::Image picture = ctx.read_pixels();
        // The corners on the screen (unsnapped) and their w, as lessons 6, 8 and 9 compute them.
        ScreenWeights weights;
        std::array<float, 3> w;
        for (int k = 0; k < 3; ++k) {
            const glm::vec4 clip = camera * glm::vec4(v[size_t(k)].position, 1.0f);
            const ScreenPoint p = to_screen(clip, kSize, kSize);
            weights.x[k] = p.x, weights.y[k] = p.y, w[size_t(k)] = clip.w;
        }
        if (std::fabs(weights.area()) < 4.0) continue;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const softraster::Rgba8 got = picture.at(x, y);
                if (got.a == 0) continue;  // (not drawn: the clear color's alpha is 0)
                const std::array<double, 3> l = weights.at(x + 0.5, y + 0.5);
                for (int c = 0; c < 3; ++c) {
                    const float want = interpolate_perspective(l, {v[0].color[c], v[1].color[c], v[2].color[c]}, w);
                    const uint8_t stored = c == 0 ? got.r : c == 1 ? got.g : got.b;
                    ASSERT_NEAR(stored / 255.0f, want, 0.5f / 255.0f + 1e-3f) << n << " at " << x << "," << y;
                }
                ++pixels;
            }
    }
    EXPECT_GT(pixels, 5000u);
}
