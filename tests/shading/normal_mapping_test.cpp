// Normal mapping (normal_mapping.h): the map's texel in the (T, B, N) frame, and the eight-lane
// form giving the same bits as the scalar one.
#include <gtest/gtest.h>

#include <bit>

#include <glm/geometric.hpp>

#include "softraster/shading/normal_mapping.h"
#include "test_support.h"

using namespace softraster;

namespace {
void expect_near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-6f) { test::expect_near(a, b, eps); }
const glm::vec3 kN(0, 0, 2), kT(3, 0, 0);  // interpolated: not unit length
}  // namespace

TEST(NormalMapping, FlatTexelKeepsTheNormal) {
    expect_near(mapped_normal(kN, glm::vec4(kT, 1), glm::vec3(0.5f, 0.5f, 1.0f), 1.0f), glm::vec3(0, 0, 1));
}

TEST(NormalMapping, TexelAxesFollowTangentAndBitangent) {
    // x of the map along T; y along B = w cross(N, T): +y for w = 1, -y for w = -1.
    expect_near(mapped_normal(kN, glm::vec4(kT, 1), glm::vec3(1.0f, 0.5f, 0.5f), 1.0f), glm::vec3(1, 0, 0));
    expect_near(mapped_normal(kN, glm::vec4(kT, 1), glm::vec3(0.5f, 1.0f, 0.5f), 1.0f), glm::vec3(0, 1, 0));
    expect_near(mapped_normal(kN, glm::vec4(kT, -1), glm::vec3(0.5f, 1.0f, 0.5f), 1.0f), glm::vec3(0, -1, 0));
}

TEST(NormalMapping, ScaleMultipliesTheTangentialPart) {
    // texel x = 0.75: m = (0.5, 0, 1); N and T interpolated at lengths 2 and 3 weight their
    // parts (MikkTSpace's form), here (1.5, 0, 2) before normalizing; a scale of 0 leaves N.
    expect_near(mapped_normal(kN, glm::vec4(kT, 1), glm::vec3(0.75f, 0.5f, 1.0f), 1.0f), glm::normalize(glm::vec3(1.5f, 0, 2)));
    expect_near(mapped_normal(kN, glm::vec4(kT, 1), glm::vec3(0.75f, 0.5f, 1.0f), 0.0f), glm::vec3(0, 0, 1));
}

TEST(NormalMapping, EightLanesMatchTheScalarBits) {
    using simd::f8;
    float nx[8], ny[8], nz[8], tx[8], ty[8], tz[8], w[8], r[8], g[8], b[8];
    for (int l = 0; l < 8; ++l) {
        nx[l] = 0.1f * float(l) - 0.3f, ny[l] = 0.7f + 0.01f * float(l), nz[l] = 0.33f;
        tx[l] = 0.9f, ty[l] = -0.05f * float(l), tz[l] = 0.2f + 0.03f * float(l);
        w[l] = l % 3 ? 1.0f : -1.0f;
        r[l] = float(37 * l % 256) / 255.0f, g[l] = float((90 + 23 * l) % 256) / 255.0f, b[l] = float(200 + l) / 255.0f;
    }
    auto load = [](const float* p) {
        f8 v;
        for (int l = 0; l < 8; ++l) v[l] = p[l];
        return v;
    };
    const simd::vec3x8 n8 = mapped_normal(simd::vec3x8{load(nx), load(ny), load(nz)}, simd::vec3x8{load(tx), load(ty), load(tz)}, load(w),
                                          simd::vec3x8{load(r), load(g), load(b)}, 0.8f);
    for (int l = 0; l < 8; ++l) {
        const glm::vec3 n = mapped_normal(glm::vec3(nx[l], ny[l], nz[l]), glm::vec4(tx[l], ty[l], tz[l], w[l]), glm::vec3(r[l], g[l], b[l]), 0.8f);
        EXPECT_EQ(std::bit_cast<uint32_t>(n.x), std::bit_cast<uint32_t>(float(n8.x[l]))) << l;
        EXPECT_EQ(std::bit_cast<uint32_t>(n.y), std::bit_cast<uint32_t>(float(n8.y[l]))) << l;
        EXPECT_EQ(std::bit_cast<uint32_t>(n.z), std::bit_cast<uint32_t>(float(n8.z[l]))) << l;
    }
}
