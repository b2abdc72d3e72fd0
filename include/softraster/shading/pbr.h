// glTF 2.0's metallic-roughness BRDF (the specification's appendix B), for one light:
//
//   c_diff = base.rgb (1 - metallic),  f0 = mix(0.04, base.rgb, metallic),  a = roughness^2
//   F   = f0 + (1 - f0) (1 - |V.H|)^5                                     (Schlick)
//   D   = a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2)                            (Trowbridge-Reitz / GGX)
//   Vis = 1 / ((|N.L| + sqrt(a^2 + (1 - a^2)(N.L)^2)) (|N.V| + sqrt(a^2 + (1 - a^2)(N.V)^2)))
//                                                                          (Smith joint, height-correlated)
//   f   = (1 - F) c_diff / pi + F D Vis
//
// and the light's contribution pi f c max(0, N.L): the factor pi makes a light's color the
// light a white diffuse surface facing it reflects, as the other shading models have it
// (docs/scene-format.md "Physically based materials").
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

inline constexpr float kPi = 3.14159265358979f;

// What the BRDF needs of the surface at one point.
struct PbrSurface {
    glm::vec3 diffuse;   // c_diff
    glm::vec3 f0;
    float alpha2;        // a^2 = roughness^4
};

// roughness: already clamped to [kMinRoughness, 1] (a smaller one makes D a spike that
// floats cannot hold).
inline constexpr float kMinRoughness = 0.03f;
inline PbrSurface pbr_surface(const glm::vec3& base, float metallic, float roughness) {
    const float a = roughness * roughness;
    return {base * (1.0f - metallic), glm::vec3(0.04f) * (1.0f - metallic) + base * metallic, a * a};
}

// pi f max(0, N.L): what one light of color 1 coming from L adds, given N.V.
inline glm::vec3 pbr_light(const PbrSurface& s, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, float nv) {
    const float nl = glm::dot(n, l);
    if (!(nl > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 hv = l + v;
    const float inv_len = 1.0f / std::sqrt(std::max(glm::dot(hv, hv), 1e-12f));
    const float nh = std::max(0.0f, glm::dot(n, hv) * inv_len), vh = std::max(0.0f, glm::dot(v, hv) * inv_len);
    const float x = 1.0f - vh, x2 = x * x, fresnel = x2 * x2 * x;
    const glm::vec3 f = s.f0 + (glm::vec3(1.0f) - s.f0) * fresnel;
    const float d_den = nh * nh * (s.alpha2 - 1.0f) + 1.0f;
    const float d = s.alpha2 / (kPi * d_den * d_den);
    const float vis_l = nl + std::sqrt(s.alpha2 + (1.0f - s.alpha2) * nl * nl);
    const float vis_v = nv + std::sqrt(s.alpha2 + (1.0f - s.alpha2) * nv * nv);
    const float vis = 1.0f / (vis_l * vis_v);
    return ((glm::vec3(1.0f) - f) * s.diffuse * (1.0f / kPi) + f * (d * vis)) * (kPi * nl);
}

// ---- the same for eight fragments (simd.h)

struct PbrSurface8 {
    simd::vec3x8 diffuse, f0;
    simd::f8 alpha2;
};

inline PbrSurface8 pbr_surface(const simd::vec3x8& base, simd::f8 metallic, simd::f8 roughness) {
    const simd::f8 a = roughness * roughness, k = 1.0f - metallic, f = 0.04f * k;
    return {{base.x * k, base.y * k, base.z * k}, {f + base.x * metallic, f + base.y * metallic, f + base.z * metallic}, a * a};
}

inline simd::vec3x8 pbr_light(const PbrSurface8& s, const simd::vec3x8& n, const simd::vec3x8& v, const simd::vec3x8& l, simd::f8 nv) {
    using simd::f8, simd::splat, simd::max;
    const f8 nl = simd::dot(n, l);
    const simd::i8 lit = nl > 0.0f;
    const simd::vec3x8 hv{l.x + v.x, l.y + v.y, l.z + v.z};
    const f8 inv_len = 1.0f / simd::sqrt(max(simd::dot(hv, hv), splat(1e-12f)));
    const f8 nh = max(splat(0.0f), simd::dot(n, hv) * inv_len), vh = max(splat(0.0f), simd::dot(v, hv) * inv_len);
    const f8 x = 1.0f - vh, x2 = x * x, fresnel = x2 * x2 * x;
    const simd::vec3x8 f{s.f0.x + (1.0f - s.f0.x) * fresnel, s.f0.y + (1.0f - s.f0.y) * fresnel, s.f0.z + (1.0f - s.f0.z) * fresnel};
    const f8 d_den = nh * nh * (s.alpha2 - 1.0f) + 1.0f;
    const f8 d = s.alpha2 / (kPi * d_den * d_den);
    const f8 vis_l = nl + simd::sqrt(s.alpha2 + (1.0f - s.alpha2) * nl * nl);
    const f8 vis_v = nv + simd::sqrt(s.alpha2 + (1.0f - s.alpha2) * nv * nv);
    const f8 vis = 1.0f / (vis_l * vis_v);
    const f8 dv = d * vis, k = kPi * nl, zero = splat(0.0f);
    return {simd::select(lit, ((1.0f - f.x) * s.diffuse.x * (1.0f / kPi) + f.x * dv) * k, zero),
            simd::select(lit, ((1.0f - f.y) * s.diffuse.y * (1.0f / kPi) + f.y * dv) * k, zero),
            simd::select(lit, ((1.0f - f.z) * s.diffuse.z * (1.0f / kPi) + f.z * dv) * k, zero)};
}

}  // namespace softraster
