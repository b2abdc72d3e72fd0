// The lighting terms of docs/scene-format.md "Shading" and "Lights", all in world space:
//   diffuse intensity  I = A + sum_i c_i max(0, N . L_i)
//   specular           S = sum_{i: N.L_i > 0} c_i specular max(0, N . H_i)^shininess   (Blinn-Phong)
//                      S = sum_{i: N.L_i > 0} c_i specular max(0, R_i . V)^shininess   (Phong)
//                      H_i = normalize(L_i + V), R_i = 2 (N . L_i) N - L_i, V = normalize(eye - P),
//                      pow(0, 0) = 1.
// A directional light: L_i = -normalize(direction_i), c_i its color. A point or spot light
// at p_i (KHR_lights_punctual): L_i = normalize(p_i - P) and c_i its color times its
// intensity times the falloff with distance d (inverse square, ended smoothly at the range)
// times, for a spot, the falloff between its inner and outer cone (positional_light below).
// A light with a shadow map has c_i times its visibility at P (shadow_mapping.h), computed
// once per fragment for all the terms (light_visibility below).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "softraster/pipeline/simd.h"
#include "softraster/shading/shadow_mapping.h"

namespace softraster {

// a^b for the specular exponent: repeated squaring for whole exponents up to 256 (the
// common case, far cheaper than powf), powf otherwise; pow(0, 0) = 1 either way.
inline float specular_power(float a, float b) {
    if (b >= 0.0f && b <= 256.0f && b == float(int(b))) {
        float result = 1.0f, base = a;
        for (unsigned e = unsigned(b); e; e >>= 1, base *= base)
            if (e & 1u) result *= base;
        return result;
    }
    return std::pow(a, b);
}

// A point or spot light, its numbers ready for the shaders.
struct PositionalLight {
    glm::vec3 position{0.0f};
    glm::vec3 color{0.0f};      // color times intensity
    float inv_range2 = 0.0f;    // 1 / range^2; 0: no range
    bool spot = false;
    glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};  // where the light travels, unit length
    float cone_scale = 0.0f, cone_offset = 0.0f;  // 1 / (cos inner - cos outer), -cos outer * scale
    int shadow = kMaxShadowedLights;              // its entry in LightVisibility (the last: none)
};

struct LightSet {
    static constexpr int kMax = 8;
    glm::vec3 ambient{0.0f};
    int count = 0;
    std::array<glm::vec3, kMax> to_light{};  // L_i, unit vectors toward each light
    std::array<glm::vec3, kMax> color{};
    // Point and spot lights, owned by whoever fills the set (the scene renderer). Only the
    // shaders that interpolate the position P read them: the scene renderer draws lambert
    // and flat surfaces lit by them with the blinn_phong shader without its specular term.
    const PositionalLight* positional = nullptr;
    int positional_count = 0;
    // The shadow maps, owned by the scene renderer, and which directional light has which.
    std::array<const ShadowMap*, kMaxShadowedLights> shadows{};
    int shadow_count = 0;
    std::array<int, kMax> shadow_of = filled(kMaxShadowedLights);

private:
    static constexpr std::array<int, kMax> filled(int v) {
        std::array<int, kMax> a{};
        a.fill(v);
        return a;
    }
};

// Each shadowed light's visibility at P; 1 for the rest.
template <class T, class P>
inline void light_visibility(const LightSet& lights, const P& p, LightVisibility<T>& vis) {
    for (int s = 0; s < lights.shadow_count; ++s) shadow_visibility(*lights.shadows[size_t(s)], p, vis[size_t(s)]);
}
inline constexpr LightVisibility<float> kFullyLit = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f};

// The direction to a positional light from P and the light's c_i there:
//   d^2 = max(|p - P|^2, 1e-8), L = (p - P) / sqrt(d^2),
//   falloff = clamp(1 - (d^2 / range^2)^2, 0, 1) / d^2   (1 / d^2 without a range),
//   spot: times clamp(dot(-L, D) scale + offset, 0, 1)^2.
inline glm::vec3 positional_light(const PositionalLight& light, const glm::vec3& p, glm::vec3& to_light) {
    const glm::vec3 lv = light.position - p;
    const float d2 = std::max(glm::dot(lv, lv), 1e-8f);
    to_light = lv / std::sqrt(d2);
    const float t = d2 * light.inv_range2;
    float k = std::min(1.0f, std::max(0.0f, 1.0f - t * t)) / d2;
    if (light.spot) {
        const float a = std::min(1.0f, std::max(0.0f, -glm::dot(to_light, light.spot_direction) * light.cone_scale + light.cone_offset));
        k *= a * a;
    }
    return light.color * k;
}

enum class Specular { BlinnPhong, Phong };

// The specular factor of one light: max(0, N . H)^shininess or max(0, R . V)^shininess.
template <Specular Sp>
inline float specular_factor(const glm::vec3& n, const glm::vec3& l, const glm::vec3& to_eye, float nl, float shininess);

// c_i times the light's visibility (times 1 is exact: unshadowed lights keep their bits).
inline glm::vec3 light_color(const LightSet& lights, int i, const LightVisibility<float>& vis) {
    return lights.color[size_t(i)] * vis[size_t(lights.shadow_of[size_t(i)])];
}

inline glm::vec3 diffuse_intensity(const LightSet& lights, const glm::vec3& n, const LightVisibility<float>& vis = kFullyLit) {
    glm::vec3 intensity = lights.ambient;
    for (int i = 0; i < lights.count; ++i)
        intensity += light_color(lights, i, vis) * std::max(0.0f, glm::dot(n, lights.to_light[size_t(i)]));
    return intensity;
}

// N . normalize(v) without normalizing v: one square root and one division.
inline float dot_normalized(const glm::vec3& n, const glm::vec3& v) { return glm::dot(n, v) / std::sqrt(glm::dot(v, v)); }

template <>
inline float specular_factor<Specular::BlinnPhong>(const glm::vec3& n, const glm::vec3& l, const glm::vec3& to_eye, float, float shininess) {
    return specular_power(std::max(0.0f, dot_normalized(n, l + to_eye)), shininess);  // N . H_i
}
template <>
inline float specular_factor<Specular::Phong>(const glm::vec3& n, const glm::vec3& l, const glm::vec3& to_eye, float nl, float shininess) {
    const glm::vec3 r = 2.0f * nl * n - l;  // reflect(-L, N)
    return specular_power(std::max(0.0f, glm::dot(r, to_eye)), shininess);
}

template <Specular Sp = Specular::BlinnPhong>
inline glm::vec3 specular_term(const LightSet& lights, const glm::vec3& n, const glm::vec3& to_eye,
                               const glm::vec3& specular, float shininess, const LightVisibility<float>& vis) {
    glm::vec3 sum(0.0f);
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3 l = lights.to_light[size_t(i)];
        const float nl = glm::dot(n, l);
        if (!(nl > 0.0f)) continue;
        sum += light_color(lights, i, vis) * specular * specular_factor<Sp>(n, l, to_eye, nl, shininess);
    }
    return sum;
}

// The point and spot lights' part of I and S at P (added after the directional lights').
template <bool WithSpecular, Specular Sp = Specular::BlinnPhong>
inline void positional_terms(const LightSet& lights, const glm::vec3& n, const glm::vec3& p, const glm::vec3& to_eye,
                             const glm::vec3& specular, float shininess, glm::vec3& diffuse, glm::vec3& spec,
                             const LightVisibility<float>& vis = kFullyLit) {
    for (int i = 0; i < lights.positional_count; ++i) {
        glm::vec3 l;
        const PositionalLight& light = lights.positional[i];
        const glm::vec3 c = positional_light(light, p, l) * vis[size_t(light.shadow)];
        const float nl = glm::dot(n, l);
        diffuse += c * std::max(0.0f, nl);
        if constexpr (WithSpecular)
            if (nl > 0.0f) spec += c * specular * specular_factor<Sp>(n, l, to_eye, nl, shininess);
    }
}

// ---- the same terms for eight fragments at once (simd.h)

inline simd::f8 specular_power(simd::f8 a, float b) {
    if (b >= 0.0f && b <= 256.0f && b == float(int(b))) {
        simd::f8 result = simd::splat(1.0f), base = a;
        for (unsigned e = unsigned(b); e; e >>= 1, base *= base)
            if (e & 1u) result *= base;
        return result;
    }
    simd::f8 r{};
    for (int l = 0; l < simd::kLanes; ++l) r[l] = std::pow(a[l], b);
    return r;
}

inline void light_color(const LightSet& lights, int i, const LightVisibility<simd::f8>& vis, simd::vec3x8& out) {
    const glm::vec3& c = lights.color[size_t(i)];
    const simd::f8& v = vis[size_t(lights.shadow_of[size_t(i)])];
    out = {c.x * v, c.y * v, c.z * v};
}

// (ambient: lights.ambient in eight lanes, broadcast once by the caller for many groups.
// Shadowed: whether a light's c_i carries its visibility; a shader without the position P
// looks no shadow up, its visibilities are all 1 and the products are left out.)
template <bool Shadowed = true>
inline simd::vec3x8 diffuse_intensity(const LightSet& lights, const simd::vec3x8& n, const LightVisibility<simd::f8>& vis,
                                      const simd::vec3x8& ambient) {
    using simd::splat;
    simd::vec3x8 sum = ambient;
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3& l = lights.to_light[size_t(i)];
        simd::vec3x8 c;
        if constexpr (Shadowed) {
            light_color(lights, i, vis, c);
        } else {
            c = simd::splat3(lights.color[size_t(i)]);
        }
        const simd::f8 nl = simd::max(splat(0.0f), n.x * l.x + n.y * l.y + n.z * l.z);
        sum.x += c.x * nl;
        sum.y += c.y * nl;
        sum.z += c.z * nl;
    }
    return sum;
}

template <Specular Sp>
inline simd::f8 specular_factor(const simd::vec3x8& n, const simd::vec3x8& l, const simd::vec3x8& to_eye, simd::f8 nl, float shininess) {
    if constexpr (Sp == Specular::BlinnPhong) {
        const simd::vec3x8 h{to_eye.x + l.x, to_eye.y + l.y, to_eye.z + l.z};
        const simd::f8 nh = simd::dot(n, h) / simd::sqrt(simd::dot(h, h));  // N . normalize(H)
        return specular_power(simd::max(simd::splat(0.0f), nh), shininess);
    } else {
        const simd::f8 k = 2.0f * nl;
        const simd::vec3x8 r{k * n.x - l.x, k * n.y - l.y, k * n.z - l.z};
        return specular_power(simd::max(simd::splat(0.0f), simd::dot(r, to_eye)), shininess);
    }
}

template <Specular Sp = Specular::BlinnPhong>
inline simd::vec3x8 specular_term(const LightSet& lights, const simd::vec3x8& n, const simd::vec3x8& to_eye,
                                  const glm::vec3& specular, float shininess, const LightVisibility<simd::f8>& vis) {
    using simd::splat;
    simd::vec3x8 sum{splat(0.0f), splat(0.0f), splat(0.0f)};
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3& l = lights.to_light[size_t(i)];
        simd::vec3x8 c;
        light_color(lights, i, vis, c);
        const simd::vec3x8 k{c.x * specular.x, c.y * specular.y, c.z * specular.z};
        const simd::f8 nl = n.x * l.x + n.y * l.y + n.z * l.z;
        const simd::i8 lit = nl > 0.0f;
        if (!simd::any(lit)) continue;
        const simd::vec3x8 lv = simd::splat3(l);
        const simd::f8 p = simd::select(lit, specular_factor<Sp>(n, lv, to_eye, nl, shininess), splat(0.0f));
        sum.x += k.x * p;
        sum.y += k.y * p;
        sum.z += k.z * p;
    }
    return sum;
}

// positional_light and positional_terms for eight fragments.
inline simd::vec3x8 positional_light(const PositionalLight& light, const simd::vec3x8& p, simd::vec3x8& to_light) {
    using simd::f8, simd::splat, simd::min, simd::max;
    const simd::vec3x8 lv{light.position.x - p.x, light.position.y - p.y, light.position.z - p.z};
    const f8 d2 = max(simd::dot(lv, lv), splat(1e-8f));
    const f8 d = simd::sqrt(d2);
    to_light = {lv.x / d, lv.y / d, lv.z / d};
    const f8 t = d2 * light.inv_range2;
    f8 k = min(splat(1.0f), max(splat(0.0f), 1.0f - t * t)) / d2;
    if (light.spot) {
        const glm::vec3 s = light.spot_direction;
        const f8 cd = -(to_light.x * s.x + to_light.y * s.y + to_light.z * s.z);
        const f8 a = min(splat(1.0f), max(splat(0.0f), cd * light.cone_scale + light.cone_offset));
        k *= a * a;
    }
    return {light.color.x * k, light.color.y * k, light.color.z * k};
}

template <bool WithSpecular, Specular Sp = Specular::BlinnPhong>
inline void positional_terms(const LightSet& lights, const simd::vec3x8& n, const simd::vec3x8& p, const simd::vec3x8& to_eye,
                             const glm::vec3& specular, float shininess, simd::vec3x8& diffuse, simd::vec3x8& spec,
                             const LightVisibility<simd::f8>& vis) {
    using simd::splat;
    for (int i = 0; i < lights.positional_count; ++i) {
        simd::vec3x8 l;
        const PositionalLight& light = lights.positional[i];
        const simd::vec3x8 c0 = positional_light(light, p, l);
        const simd::f8 v = vis[size_t(light.shadow)];
        const simd::vec3x8 c{c0.x * v, c0.y * v, c0.z * v};
        const simd::f8 nl = simd::dot(n, l);
        const simd::f8 nl0 = simd::max(splat(0.0f), nl);
        diffuse.x += c.x * nl0;
        diffuse.y += c.y * nl0;
        diffuse.z += c.z * nl0;
        if constexpr (WithSpecular) {
            const simd::i8 lit = nl > 0.0f;
            if (!simd::any(lit)) continue;
            const simd::f8 f = simd::select(lit, specular_factor<Sp>(n, l, to_eye, nl, shininess), splat(0.0f));
            spec.x += c.x * specular.x * f;
            spec.y += c.y * specular.y * f;
            spec.z += c.z * specular.z * f;
        }
    }
}

}  // namespace softraster
