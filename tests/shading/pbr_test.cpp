// The metallic-roughness BRDF (pbr.h) against the formulas of glTF's appendix B evaluated
// independently in double precision, and by its physical properties: reciprocity and
// energy conservation.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "softraster/shading/pbr.h"

using namespace softraster;

namespace {

// pi f (N.L) for one channel, written out from the specification in double precision.
double reference(double base, double metallic, double roughness, const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l) {
    const double pi = 3.14159265358979323846;
    const double nl = glm::dot(n, l), nv = std::max(0.0, glm::dot(n, v));
    if (nl <= 0) return 0;
    const glm::dvec3 h = glm::normalize(l + v);
    const double c_diff = base * (1 - metallic), f0 = 0.04 * (1 - metallic) + base * metallic;
    const double a = roughness * roughness, a2 = a * a;
    const double f = f0 + (1 - f0) * std::pow(1 - std::max(0.0, glm::dot(v, h)), 5);
    const double nh = std::max(0.0, glm::dot(n, h));
    const double d = a2 / (pi * std::pow(nh * nh * (a2 - 1) + 1, 2));
    const double vis = 1 / ((nl + std::sqrt(a2 + (1 - a2) * nl * nl)) * (nv + std::sqrt(a2 + (1 - a2) * nv * nv)));
    return ((1 - f) * c_diff / pi + f * d * vis) * pi * nl;
}

glm::vec3 unit(std::mt19937& rng) {  // a random direction in the upper hemisphere (z > 0.05)
    std::normal_distribution<float> g;
    for (;;) {
        glm::vec3 d(g(rng), g(rng), std::abs(g(rng)));
        if (glm::length(d) > 1e-3f && glm::normalize(d).z > 0.05f) return glm::normalize(d);
    }
}

}  // namespace

TEST(Pbr, MatchesTheSpecificationsFormulas) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const glm::vec3 n(0, 0, 1);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 v = unit(rng), l = unit(rng);
        const float base = u01(rng), metallic = u01(rng) < 0.3f ? float(i % 2) : u01(rng);
        const float roughness = std::max(0.1f, u01(rng));  // (sharper peaks: float cancellation near N.H = 1)
        const PbrSurface s = pbr_surface(glm::vec3(base), metallic, roughness);
        const float got = pbr_light(s, n, v, l, std::max(0.0f, glm::dot(n, v))).x;
        const double want = reference(base, metallic, roughness, glm::dvec3(n), glm::dvec3(v), glm::dvec3(l));
        EXPECT_NEAR(got, want, 1e-4 * std::max(1.0, want)) << "base " << base << " metallic " << metallic << " roughness " << roughness;
    }
    // Below the horizon: nothing.
    const PbrSurface s = pbr_surface(glm::vec3(0.5f), 0.0f, 0.5f);
    EXPECT_EQ(pbr_light(s, n, glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 0, -0.1f)), 1.0f), glm::vec3(0.0f));
}

// f(L, V) = f(V, L): swapping the light and the eye changes nothing but the cosine factor.
TEST(Pbr, Reciprocity) {
    std::mt19937 rng(5);
    const glm::vec3 n(0, 0, 1);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 v = unit(rng), l = unit(rng);
        const PbrSurface s = pbr_surface(glm::vec3(0.2f, 0.5f, 0.9f), float(i % 3) * 0.5f, 0.1f + 0.9f * float(i % 7) / 6.0f);
        const glm::vec3 a = pbr_light(s, n, v, l, v.z) / l.z, b = pbr_light(s, n, l, v, l.z) / v.z;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 2e-4f * std::max(1.0f, a[c]));
    }
}

// Energy: the light a surface reflects toward V, integrated over every light direction of the
// hemisphere (1/pi of the integral of pi f N.L for a unit light). For a white metal at
// roughness 1 it has a closed form: D = 1/pi, Vis = 1/((1 + N.L)(1 + N.V)) and F = 1 give
// 2 (1 - ln 2) / (1 + N.V), about 0.31 seen head-on (the single-scattering model loses the
// light that bounces between microfacets). A rough white dielectric reflects nearly all,
// at grazing views a few percent more than arrives: glTF's mix of (1 - F) diffuse and the
// specular lobe is not exactly energy conserving.
TEST(Pbr, ConservesEnergy) {
    const glm::vec3 n(0, 0, 1);
    for (float metallic : {0.0f, 1.0f})
        for (float roughness : {0.5f, 0.75f, 1.0f})  // (narrower lobes need a finer grid)
            for (float view : {0.0f, 0.6f, 1.2f}) {
                const glm::vec3 v(std::sin(view), 0, std::cos(view));
                const PbrSurface s = pbr_surface(glm::vec3(1.0f), metallic, roughness);
                double albedo = 0;
                const int steps = 400;  // midpoint rule over (cos theta, phi)
                for (int i = 0; i < steps; ++i)
                    for (int j = 0; j < steps; ++j) {
                        const double ct = (i + 0.5) / steps, st = std::sqrt(1 - ct * ct), phi = 2 * 3.14159265358979 * (j + 0.5) / steps;
                        const glm::vec3 l(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct));
                        albedo += pbr_light(s, n, v, l, v.z).x;
                    }
                albedo *= (1.0 / steps) * (2 * 3.14159265358979 / steps) / 3.14159265358979;
                const std::string where = "metallic " + std::to_string(metallic) + " roughness " + std::to_string(roughness) +
                                          " view " + std::to_string(view);
                EXPECT_LE(albedo, 1.04) << where;
                if (metallic == 0.0f) {
                    EXPECT_GT(albedo, 0.9) << where;
                }
                if (metallic == 1.0f && roughness == 1.0f) {
                    EXPECT_NEAR(albedo, 2 * (1 - std::log(2.0)) / (1 + v.z), 2e-3) << where;
                }
                if (metallic == 1.0f) {
                    EXPECT_GT(albedo, 0.3) << where;
                }
            }
}

// Eight at a time: the same bits as one at a time.
TEST(Pbr, EightAtOnceEqualOneAtATime) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), sym(-1.0f, 1.0f);
    for (int trial = 0; trial < 200; ++trial) {
        simd::vec3x8 base, n, v, l;
        simd::f8 metallic, roughness, nv;
        for (int k = 0; k < simd::kLanes; ++k) {
            const glm::vec3 nn = glm::normalize(glm::vec3(sym(rng), sym(rng), sym(rng)) + glm::vec3(0, 0, 0.01f));
            const glm::vec3 vv = glm::normalize(glm::vec3(sym(rng), sym(rng), sym(rng)) + glm::vec3(0.01f, 0, 0));
            const glm::vec3 ll = glm::normalize(glm::vec3(sym(rng), sym(rng), sym(rng)) + glm::vec3(0, 0.01f, 0));
            base.x[k] = u01(rng), base.y[k] = u01(rng), base.z[k] = u01(rng);
            n.x[k] = nn.x, n.y[k] = nn.y, n.z[k] = nn.z;
            v.x[k] = vv.x, v.y[k] = vv.y, v.z[k] = vv.z;
            l.x[k] = ll.x, l.y[k] = ll.y, l.z[k] = ll.z;
            metallic[k] = u01(rng), roughness[k] = std::max(kMinRoughness, u01(rng));
            nv[k] = std::max(0.0f, glm::dot(nn, vv));
        }
        const simd::vec3x8 got = pbr_light(pbr_surface(base, metallic, roughness), n, v, l, nv);
        for (int k = 0; k < simd::kLanes; ++k) {
            const PbrSurface s = pbr_surface(glm::vec3(base.x[k], base.y[k], base.z[k]), metallic[k], roughness[k]);
            const glm::vec3 want = pbr_light(s, glm::vec3(n.x[k], n.y[k], n.z[k]), glm::vec3(v.x[k], v.y[k], v.z[k]),
                                             glm::vec3(l.x[k], l.y[k], l.z[k]), nv[k]);
            EXPECT_EQ(got.x[k], want.x);
            EXPECT_EQ(got.y[k], want.y);
            EXPECT_EQ(got.z[k], want.z);
        }
    }
}
