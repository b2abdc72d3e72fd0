// Screen-space ambient occlusion (ambient_occlusion.h): the kernel, what occludes and what
// does not (a valley darkens, a ridge and open slopes do not), background pixels, threads,
// and how the picture is darkened.
#include <cmath>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "softraster/shading/ambient_occlusion.h"
#include "softraster/worker_pool.h"

using namespace softraster;

namespace {

constexpr int kSize = 64;

// A depth buffer of the surface z = surface(x, y) in view space, seen through an
// orthographic camera 2 units wide (x, y in [-1, 1]; row 0 at the top), or nothing (depth
// 1) where surface returns NaN.
std::vector<float> depth_of(const glm::mat4& proj, const std::function<float(float, float)>& surface) {
    std::vector<float> depth(size_t(kSize) * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float vx = 2.0f * (float(x) + 0.5f) / kSize - 1.0f, vy = 1.0f - 2.0f * (float(y) + 0.5f) / kSize;
            const float z = surface(vx, vy);
            const glm::vec4 clip = proj * glm::vec4(vx, vy, z, 1.0f);
            depth[size_t(y) * kSize + size_t(x)] = std::isnan(z) ? 1.0f : 0.5f * clip.z / clip.w + 0.5f;
        }
    return depth;
}

const glm::mat4 kOrtho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);

}  // namespace

TEST(AmbientOcclusion, KernelFillsTheUnitDisk) {
    const auto& k = ambient_occlusion_kernel();
    for (int i = 0; i < kAmbientOcclusionSamples; ++i) {
        EXPECT_NEAR(std::hypot(k[size_t(i)].x, k[size_t(i)].y), std::sqrt((i + 0.5) / 16.0), 1e-6) << i;
        EXPECT_LT(std::hypot(k[size_t(i)].x, k[size_t(i)].y), 1.0f);
    }
    EXPECT_NE(k[1], k[2]);
}

// Open surfaces, flat or sloped, are not occluded: their neighbours lie in their tangent plane.
TEST(AmbientOcclusion, OpenSurfacesStayLit) {
    AmbientOcclusionSettings s;
    s.radius = 0.3f;
    for (const auto& surface : std::vector<std::function<float(float, float)>>{
             [](float, float) { return -3.0f; }, [](float x, float y) { return -3.0f + 0.7f * x - 0.4f * y; }}) {
        const std::vector<float> ao = ambient_occlusion(depth_of(kOrtho, surface).data(), kSize, kSize, kOrtho, s);
        for (float f : ao) ASSERT_EQ(f, 1.0f);
    }
    // The same under a perspective camera: a floor seen at a grazing angle.
    const glm::mat4 persp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 50.0f);
    std::vector<float> depth(size_t(kSize) * kSize, 1.0f);
    for (int y = kSize / 2 + 2; y < kSize; ++y)  // the floor y = -1 below the horizon: z = -1 / (ndc_y tan 30)
        for (int x = 0; x < kSize; ++x) {
            const float ny = 1.0f - 2.0f * (float(y) + 0.5f) / kSize, z = 1.0f / (ny * std::tan(glm::radians(30.0f)));
            const glm::vec4 clip = persp * glm::vec4(0.0f, -1.0f, z, 1.0f);
            depth[size_t(y) * kSize + size_t(x)] = 0.5f * clip.z / clip.w + 0.5f;
        }
    for (float f : ambient_occlusion(depth.data(), kSize, kSize, persp, s)) ASSERT_EQ(f, 1.0f);
}

// A valley (its floor farthest from the camera) darkens along its crease and nowhere far
// from it; a ridge does not darken at all; nothing drawn keeps 1.
TEST(AmbientOcclusion, ValleysDarkenRidgesDoNot) {
    AmbientOcclusionSettings s;
    s.radius = 0.3f;
    const auto valley = depth_of(kOrtho, [](float x, float) { return -3.0f + std::abs(x); });
    const std::vector<float> ao = ambient_occlusion(valley.data(), kSize, kSize, kOrtho, s);
    for (int y = 0; y < kSize; ++y) {
        EXPECT_LT(ao[size_t(y) * kSize + kSize / 2], 0.9f) << y;  // at the crease
        EXPECT_EQ(ao[size_t(y) * kSize + 2], 1.0f) << y;          // 0.9 units away: beyond the radius
    }
    const auto ridge = depth_of(kOrtho, [](float x, float) { return -3.0f - std::abs(x); });
    for (float f : ambient_occlusion(ridge.data(), kSize, kSize, kOrtho, s)) ASSERT_EQ(f, 1.0f);
    // A stronger setting darkens more; intensity 0 not at all.
    AmbientOcclusionSettings strong = s;
    strong.intensity = 4.0f;
    EXPECT_LT(ambient_occlusion(valley.data(), kSize, kSize, kOrtho, strong)[kSize / 2], ao[kSize / 2]);
    AmbientOcclusionSettings none = s;
    none.intensity = 0.0f;
    for (float f : ambient_occlusion(valley.data(), kSize, kSize, kOrtho, none)) ASSERT_EQ(f, 1.0f);
    // A box standing in front of the wall: the wall pixels next to it are not occluded by it
    // beyond the radius (the fade), and the background keeps 1.
    const auto holes = depth_of(kOrtho, [](float x, float) { return x > 0.5f ? NAN : -3.0f + std::abs(x); });
    const std::vector<float> with_holes = ambient_occlusion(holes.data(), kSize, kSize, kOrtho, s);
    for (int y = 0; y < kSize; ++y) EXPECT_EQ(with_holes[size_t(y) * kSize + kSize - 1], 1.0f);
}

TEST(AmbientOcclusion, ThreadsDoNotChangeTheFactors) {
    AmbientOcclusionSettings s;
    s.radius = 0.25f;
    const auto bumps = depth_of(kOrtho, [](float x, float y) { return -3.0f + 0.3f * std::sin(7 * x) * std::cos(5 * y); });
    WorkerPool pool(3);
    EXPECT_EQ(ambient_occlusion(bumps.data(), kSize, kSize, kOrtho, s), ambient_occlusion(bumps.data(), kSize, kSize, kOrtho, s, &pool));
}

TEST(AmbientOcclusion, DarkensColorsNotAlpha) {
    Image img(2, 1);
    img.pixels = {{200, 100, 3, 77}, {200, 100, 3, 77}};
    Image linear = img, srgb = img;
    apply_ambient_occlusion(linear, {0.5f, 1.0f}, ColorSpace::Linear);
    EXPECT_EQ(linear.pixels[0], (Rgba8{100, 50, 2, 77}));  // floor(1.5 + 0.5) = 2
    EXPECT_EQ(linear.pixels[1], img.pixels[1]);
    apply_ambient_occlusion(srgb, {0.5f, 1.0f}, ColorSpace::Srgb);
    EXPECT_EQ(srgb.pixels[0].r, srgb::encode(srgb::decode(200) * 0.5f));
    EXPECT_LT(srgb.pixels[0].r, 200);
    EXPECT_GT(srgb.pixels[0].r, 100);  // half the light is more than half the stored value
    EXPECT_EQ(srgb.pixels[0].a, 77);
}
