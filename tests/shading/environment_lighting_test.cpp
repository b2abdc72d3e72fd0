// Image-based lighting (environment_lighting.h): the maps of environments whose lighting is
// known in closed form, the split sum's table against a brute-force integral, and reading
// Radiance HDR files.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <string>

#include "softraster/error.h"
#include "softraster/shading/environment_lighting.h"
#include "test_support.h"

using namespace softraster;

namespace {

EquirectImage picture(int w, int h, glm::vec3 (*radiance)(const glm::vec3&)) {
    EquirectImage m{w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double p = 2.0 * M_PI * ((i + 0.5) / w - 0.5), t = M_PI * (j + 0.5) / h;
            m.texels[size_t(j * w + i)] = radiance(glm::vec3(std::sin(t) * std::sin(p), std::cos(t), -std::sin(t) * std::cos(p)));
        }
    return m;
}

glm::vec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

}  // namespace

// The white furnace: under a uniform white environment E/pi = 1 and S = 1 everywhere, so a
// white dielectric of any roughness reflects exactly the environment's intensity.
TEST(EnvironmentLighting, WhiteFurnace) {
    const EnvironmentLighting e = prepare_environment(picture(512, 256, [](const glm::vec3&) { return glm::vec3(1.0f); }), 0.6f);
    std::mt19937 rng(3);
    for (int k = 0; k < 200; ++k) {
        const glm::vec3 n = random_direction(rng), v = random_direction(rng);
        const float roughness = std::uniform_real_distribution<float>(0.03f, 1.0f)(rng);
        EXPECT_NEAR(environment_irradiance(e, n).g, 1.0f, 2e-4f);
        EXPECT_NEAR(environment_specular(e, v, roughness).r, 1.0f, 1e-5f);
        const float nv = std::max(0.0f, glm::dot(n, v));
        const glm::vec3 c = environment_light(e, glm::vec3(1.0f), glm::vec3(0.04f), n, v, nv, roughness, 1.0f);
        EXPECT_NEAR(c.b, 0.6f, 2e-4f);
    }
}

// A sky whose radiance is max(0, d.y): a surface facing up receives E/pi = 2/3 (the integral
// of cos^2 over the upper hemisphere, over pi), one facing down nothing, one facing the
// horizon 2 / (3 pi) (the integral of max(0, y) max(0, x), 2/3, over pi); nine coefficients
// come within a few hundredths of these.
TEST(EnvironmentLighting, IrradianceOfAClampedCosineSky) {
    const EnvironmentLighting e = prepare_environment(picture(256, 128, [](const glm::vec3& d) { return glm::vec3(std::max(0.0f, d.y)); }), 1.0f);
    EXPECT_NEAR(environment_irradiance(e, {0, 1, 0}).r, 2.0f / 3.0f, 0.03f);
    EXPECT_NEAR(environment_irradiance(e, {0, -1, 0}).r, 0.0f, 0.03f);
    EXPECT_NEAR(environment_irradiance(e, {1, 0, 0}).r, 2.0f / (3.0f * float(M_PI)), 0.03f);
    // A sharp lobe's prefiltered levels: the mirror level keeps the sky, the rough ones blur it.
    EXPECT_NEAR(environment_specular(e, {0, 1, 0}, 0.0f).r, 1.0f, 0.01f);
    EXPECT_LT(environment_specular(e, {0, 1, 0}, 1.0f).r, 0.9f);
    EXPECT_GT(environment_specular(e, {0, -1, 0}, 1.0f).r, 0.0f);
}

// A and B at a table texel's center against the integral over the hemisphere by the midpoint
// rule (no importance sampling): A = int D Vis (1 - Fc) N.L, B = int D Vis Fc N.L.
TEST(EnvironmentLighting, SplitSumTableMatchesTheIntegral) {
    const EnvironmentLighting e = prepare_environment(picture(8, 4, [](const glm::vec3&) { return glm::vec3(1.0f); }), 1.0f);
    constexpr int n = EnvironmentLighting::kLutSize;
    for (auto [i, j] : {std::pair{15, 15}, std::pair{28, 8}, std::pair{6, 24}}) {
        const double nv = (i + 0.5) / n, roughness = (j + 0.5) / n, a2 = std::pow(roughness, 4.0);
        const glm::dvec3 v(std::sqrt(1 - nv * nv), 0, nv);
        double a = 0, b = 0;
        constexpr int kT = 600, kP = 1200;
        for (int ti = 0; ti < kT; ++ti)
            for (int pi = 0; pi < kP; ++pi) {
                const double t = (ti + 0.5) * (M_PI / 2) / kT, p = (pi + 0.5) * 2 * M_PI / kP;
                const glm::dvec3 l(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                const glm::dvec3 h = glm::normalize(l + v);
                const double nl = l.z, nh = h.z, vh = glm::dot(v, h);
                const double dd = nh * nh * (a2 - 1) + 1, d = a2 / (M_PI * dd * dd);
                const double vis = 1 / ((nl + std::sqrt(a2 + (1 - a2) * nl * nl)) * (nv + std::sqrt(a2 + (1 - a2) * nv * nv)));
                const double fc = std::pow(1 - vh, 5), w = d * vis * nl * std::sin(t) * (M_PI / 2 / kT) * (2 * M_PI / kP);
                a += (1 - fc) * w;
                b += fc * w;
            }
        const glm::vec2 ab = environment_brdf(e, float(nv), float(roughness));
        EXPECT_NEAR(ab.x, a, 0.02) << i << ", " << j;
        EXPECT_NEAR(ab.y, b, 0.01) << i << ", " << j;
    }
}

// Eight fragments at once (environment_light8) give each lane the bits of one at a time, on
// both CPU paths: the reflected direction all around the picture (its seam at u = 0 and 1, the
// poles), every level and the last alone, the table's edges.
TEST(EnvironmentLighting, EightLanesEqualOneAtATimeOnBothPaths) {
    const EnvironmentLighting e = prepare_environment(
        picture(300, 150, [](const glm::vec3& d) { return glm::vec3(1.0f + d.x, 0.5f + 0.5f * d.y * d.y, std::max(0.0f, d.z) + 0.1f * d.x * d.y); }), 0.8f);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float roughnesses[] = {0.03f, 0.2f, 0.4f, 0.5f, 0.8f, 0.99f, 1.0f};
    for (const bool generic : {false, true}) {
        SCOPED_TRACE(generic ? "generic path" : "best path");
        simd::use_generic_path(generic);
        for (int round = 0; round < 400; ++round) {
            simd::vec3x8 c_diff, f0, n, v, out;
            simd::f8 nv, roughness, occlusion;
            for (int k = 0; k < simd::kLanes; ++k) {
                glm::vec3 nk = random_direction(rng), vk = random_direction(rng);
                if (round % 5 == 0) nk = glm::normalize(glm::vec3(0.0f, 1.0f, 1e-4f * float(k - 4))), vk = {0.0f, 0.0f, -1.0f};  // R near the seam
                if (round % 7 == 0) nk = vk;                                                                                       // R = V
                const float r = round % 2 ? roughnesses[(round / 2 + k) % 7] : 0.03f + 0.97f * unit(rng);
                n.x[k] = nk.x, n.y[k] = nk.y, n.z[k] = nk.z, v.x[k] = vk.x, v.y[k] = vk.y, v.z[k] = vk.z;
                nv[k] = round % 3 ? std::max(0.0f, glm::dot(nk, vk)) : float(k % 2);
                roughness[k] = r, occlusion[k] = unit(rng);
                c_diff.x[k] = unit(rng), c_diff.y[k] = unit(rng), c_diff.z[k] = unit(rng);
                f0.x[k] = unit(rng), f0.y[k] = unit(rng), f0.z[k] = unit(rng);
            }
            environment_light8(e, c_diff, f0, n, v, nv, roughness, occlusion, out);
            for (int k = 0; k < simd::kLanes; ++k) {
                const glm::vec3 one = environment_light(e, {c_diff.x[k], c_diff.y[k], c_diff.z[k]}, {f0.x[k], f0.y[k], f0.z[k]},
                                                        {n.x[k], n.y[k], n.z[k]}, {v.x[k], v.y[k], v.z[k]}, nv[k], roughness[k], occlusion[k]);
                ASSERT_EQ(std::bit_cast<glm::uvec3>(glm::vec3(out.x[k], out.y[k], out.z[k])), std::bit_cast<glm::uvec3>(one))
                    << "round " << round << " lane " << k << " roughness " << roughness[k];
            }
        }
    }
    simd::use_generic_path(false);
}

// A Radiance file written by hand (flat RGBE: 128, 128, 128, 129 is 1.0), and its errors.
TEST(EnvironmentLighting, ReadsRadianceHdr) {
    std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int k = 0; k < 8; ++k) bytes += k == 5 ? std::string("\x80\x40\x20\x82", 4) : std::string("\x80\x80\x80\x81", 4);
    const EquirectImage m = read_environment(test::write_temp_file("softraster_env_tests", "sky.hdr", bytes));
    ASSERT_EQ(m.width, 4);
    ASSERT_EQ(m.height, 2);
    EXPECT_EQ(m.at(0, 0), glm::vec3(1.0f));
    EXPECT_EQ(m.at(1, 1), glm::vec3(2.0f, 1.0f, 0.5f));  // (128, 64, 32) / 256 * 2^(130 - 128)
    auto error_of = [](const std::string& name, const std::string& contents) {
        return test::error_of([&] { read_environment(test::write_temp_file("softraster_env_tests", name, contents)); });
    };
    EXPECT_NE(error_of("cut.hdr", bytes.substr(0, bytes.size() - 9)).find("cut.hdr: corrupt Radiance HDR"), std::string::npos);
    EXPECT_NE(error_of("sky.png", bytes).find("sky.png: an environment is an .hdr or .exr picture"), std::string::npos);
    EXPECT_NE(error_of("none.exr", "not an exr").find("none.exr: corrupt OpenEXR"), std::string::npos);
}
