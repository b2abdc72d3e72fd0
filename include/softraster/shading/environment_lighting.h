// Image-based lighting (docs/scene-format.md "Environment lighting"): an equirectangular
// HDR picture of everything around the scene lights pbr surfaces, split as in Karis's
// "Real Shading in Unreal Engine 4" (2013):
//
//   diffuse:  E(N)/pi, the irradiance, from nine spherical-harmonic coefficients (Ramamoorthi
//             and Hanrahan 2001, "An efficient representation for irradiance environment maps")
//   specular: S(R, roughness) (the environment prefiltered with the GGX lobe, one level per
//             roughness step) times f0 A + B, A and B from a lookup table of (N.V, roughness)
//
// added to a pbr fragment as (c_diff E/pi (1 - k) + S k) occlusion intensity, k = f0 A + B.
// The maps are computed once when the scene loads (environment_lighting.cpp); both
// renderers read the same numbers.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

// A picture held elsewhere (one level of the specular chain below), read as EquirectImage.
struct EquirectView {
    const glm::vec3* texels = nullptr;  // row by row from the top
    int width = 0, height = 0;
    const glm::vec3& at(int i, int j) const { return texels[size_t(j) * size_t(width) + size_t(i)]; }
};
// An equirectangular picture: texel (i, j) of a w x h picture is seen in the direction
// (sin t sin p, cos t, -sin t cos p), p = 2 pi ((i + 1/2)/w - 1/2), t = pi (j + 1/2)/h:
// row 0 looks up (+y), the middle of the picture looks down -z.
struct EquirectImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;  // row by row from the top
    const glm::vec3& at(int i, int j) const { return texels[size_t(j) * size_t(width) + size_t(i)]; }
    operator EquirectView() const { return {texels.data(), width, height}; }
};

struct EnvironmentLighting {
    static constexpr int kBaseWidth = 256, kBaseHeight = 128;  // the specular maps' level 0
    static constexpr int kLevels = 6;                          // level k: roughness k / 5
    static constexpr int kLutSize = 32;                        // (N.V, roughness) texels
    // E(N)/pi = k0 + k1 y + k2 z + k3 x + k4 xy + k5 yz + k6 (3 z^2 - 1) + k7 xz + k8 (x^2 - y^2)
    std::array<glm::vec3, 9> irradiance{};
    // The specular levels one after another, level k ((256 >> k) x (128 >> k)) from texel
    // level_offset(k) on, and two texels of padding: in one array, eight lanes on different
    // levels read it with one load each (environment_lanes.cpp).
    std::vector<glm::vec3> specular;
    static constexpr int level_offset(int k) {
        int at = 0;
        for (int l = 0; l < k; ++l) at += (kBaseWidth >> l) * (kBaseHeight >> l);
        return at;
    }
    EquirectView specular_level(int k) const { return {specular.data() + level_offset(k), kBaseWidth >> k, kBaseHeight >> k}; }
    std::vector<glm::vec2> lut;                   // A, B at ((i + 1/2)/32, (j + 1/2)/32), row j by roughness
    float intensity = 1.0f;
    EquirectImage picture;    // as read: the background (sky_shader.h)
    bool background = false;  // the picture behind the scene instead of its background color
};

// Where a direction falls in an equirectangular picture, in [0, 1]^2 (u across, v down):
// (1/2 + atan2(d.x, -d.z) / 2 pi, acos(d.y) / pi). The angles come from SLEEF's functions
// that give the same bits on every instruction set (its "cinz" ones, within 1 ulp), so that
// eight lanes at once (environment_lanes.cpp) give what one at a time gives here.
glm::vec2 equirect_uv(const glm::vec3& d);
inline constexpr float kInvTwoPi = 0.159154943091895f, kInvPi = 0.318309886183791f;  // (its scales)

// GL's bilinear filter at uv: across wraps around (GL_REPEAT), down is clamped to the edge.
inline glm::vec3 sample_bilinear(const EquirectView& m, const glm::vec2& uv) {
    const float x = uv.x * float(m.width) - 0.5f, y = uv.y * float(m.height) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const float ax = x - fx0, ay = y - fy0;
    const int i0 = int(fx0), j0 = int(fy0);
    auto wrap = [&](int i) { return ((i % m.width) + m.width) % m.width; };
    auto clamp = [&](int j) { return std::clamp(j, 0, m.height - 1); };
    const glm::vec3 top = m.at(wrap(i0), clamp(j0)) * (1.0f - ax) + m.at(wrap(i0 + 1), clamp(j0)) * ax;
    const glm::vec3 bottom = m.at(wrap(i0), clamp(j0 + 1)) * (1.0f - ax) + m.at(wrap(i0 + 1), clamp(j0 + 1)) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

// E(N)/pi at a unit normal, clamped at 0 (nine coefficients can ring below it).
inline glm::vec3 environment_irradiance(const EnvironmentLighting& e, const glm::vec3& n) {
    const std::array<glm::vec3, 9>& k = e.irradiance;
    const glm::vec3 sum = k[0] + k[1] * n.y + k[2] * n.z + k[3] * n.x + k[4] * (n.x * n.y) + k[5] * (n.y * n.z) +
                          k[6] * (3.0f * n.z * n.z - 1.0f) + k[7] * (n.x * n.z) + k[8] * (n.x * n.x - n.y * n.y);
    return glm::max(sum, glm::vec3(0.0f));
}

// S(R, roughness): the levels as a mipmap read with GL_LINEAR_MIPMAP_LINEAR at lod = 5 roughness.
inline glm::vec3 environment_specular(const EnvironmentLighting& e, const glm::vec3& r, float roughness) {
    const glm::vec2 uv = equirect_uv(r);
    const float lod = std::clamp(roughness * float(EnvironmentLighting::kLevels - 1), 0.0f, float(EnvironmentLighting::kLevels - 1));
    const int l0 = int(lod);
    const float f = lod - float(l0);
    const glm::vec3 a = sample_bilinear(e.specular_level(l0), uv);
    if (l0 + 1 >= EnvironmentLighting::kLevels) return a;
    return a * (1.0f - f) + sample_bilinear(e.specular_level(l0 + 1), uv) * f;
}

// A and B at (N.V, roughness), bilinear with the edges clamped (GL_CLAMP_TO_EDGE).
inline glm::vec2 environment_brdf(const EnvironmentLighting& e, float nv, float roughness) {
    constexpr int n = EnvironmentLighting::kLutSize;
    const float x = nv * float(n) - 0.5f, y = roughness * float(n) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const float ax = x - fx0, ay = y - fy0;
    auto at = [&](int i, int j) { return e.lut[size_t(std::clamp(j, 0, n - 1) * n + std::clamp(i, 0, n - 1))]; };
    const int i0 = int(fx0), j0 = int(fy0);
    const glm::vec2 top = at(i0, j0) * (1.0f - ax) + at(i0 + 1, j0) * ax;
    const glm::vec2 bottom = at(i0, j0 + 1) * (1.0f - ax) + at(i0 + 1, j0 + 1) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

// What the environment adds to a pbr fragment: N, V unit, nv = max(0, N.V), roughness
// clamped as the lights have it.
inline glm::vec3 environment_light(const EnvironmentLighting& e, const glm::vec3& c_diff, const glm::vec3& f0, const glm::vec3& n,
                                   const glm::vec3& v, float nv, float roughness, float occlusion) {
    const glm::vec3 r = 2.0f * glm::dot(n, v) * n - v;  // reflect(-V, N)
    const glm::vec2 ab = environment_brdf(e, nv, roughness);
    const glm::vec3 k = f0 * ab.x + ab.y;
    const glm::vec3 diffuse = c_diff * environment_irradiance(e, n) * (1.0f - k);
    return (diffuse + environment_specular(e, r, roughness) * k) * (occlusion * e.intensity);
}

// environment_light for eight fragments at once (environment_lanes.cpp), lane by lane the
// same operations in the same order, so each lane has the bits environment_light gives.
// (The vectors by reference: the function is called from both CPU paths, simd.h.)
void environment_light8(const EnvironmentLighting& e, const simd::vec3x8& c_diff, const simd::vec3x8& f0, const simd::vec3x8& n,
                        const simd::vec3x8& v, const simd::f8& nv, const simd::f8& roughness, const simd::f8& occlusion,
                        simd::vec3x8& out);

// Reads an .hdr (Radiance) or .exr picture as an equirectangular environment. Throws
// InputError naming the file for a missing, truncated or corrupt one.
EquirectImage read_environment(const std::filesystem::path& path);
// The maps (the spherical harmonics, the prefiltered levels, the lookup table).
EnvironmentLighting prepare_environment(const EquirectImage& picture, float intensity, bool background = false);

}  // namespace softraster
