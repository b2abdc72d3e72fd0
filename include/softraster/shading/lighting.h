// The spec's lighting terms (spec "Shading"), all in world space:
//   diffuse intensity  I = A + sum_i c_i max(0, N . L_i),            L_i = -normalize(direction_i)
//   specular           S = sum_{i: N.L_i > 0} c_i specular max(0, N . H_i)^shininess,
//                      H_i = normalize(L_i + V), V = normalize(eye - P), pow(0, 0) = 1.
#pragma once
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "softraster/pipeline/simd.h"

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

struct LightSet {
    static constexpr int kMax = 8;
    glm::vec3 ambient{0.0f};
    int count = 0;
    std::array<glm::vec3, kMax> to_light{};  // L_i, unit vectors toward each light
    std::array<glm::vec3, kMax> color{};
};

inline glm::vec3 diffuse_intensity(const LightSet& lights, const glm::vec3& n) {
    glm::vec3 intensity = lights.ambient;
    for (int i = 0; i < lights.count; ++i)
        intensity += lights.color[size_t(i)] * std::max(0.0f, glm::dot(n, lights.to_light[size_t(i)]));
    return intensity;
}

// N . normalize(v) without normalizing v: one square root and one division.
inline float dot_normalized(const glm::vec3& n, const glm::vec3& v) { return glm::dot(n, v) / std::sqrt(glm::dot(v, v)); }

inline glm::vec3 specular_term(const LightSet& lights, const glm::vec3& n, const glm::vec3& to_eye,
                               const glm::vec3& specular, float shininess) {
    glm::vec3 sum(0.0f);
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3 l = lights.to_light[size_t(i)];
        if (!(glm::dot(n, l) > 0.0f)) continue;
        const float nh = dot_normalized(n, l + to_eye);  // N . H_i
        sum += lights.color[size_t(i)] * specular * specular_power(std::max(0.0f, nh), shininess);
    }
    return sum;
}

// ---- the same terms for eight fragments at once (simd.h)

inline simd::f8 specular_power(simd::f8 a, float b) {
    if (b >= 0.0f && b <= 256.0f && b == float(int(b))) {
        simd::f8 result = simd::splat(1.0f), base = a;
        for (unsigned e = unsigned(b); e; e >>= 1, base *= base)
            if (e & 1u) result *= base;
        return result;
    }
    simd::f8 r;
    for (int l = 0; l < simd::kLanes; ++l) r[l] = std::pow(a[l], b);
    return r;
}

inline simd::vec3x8 diffuse_intensity(const LightSet& lights, const simd::vec3x8& n) {
    using simd::splat;
    simd::vec3x8 sum{splat(lights.ambient.x), splat(lights.ambient.y), splat(lights.ambient.z)};
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3 l = lights.to_light[size_t(i)], c = lights.color[size_t(i)];
        const simd::f8 nl = simd::max(splat(0.0f), n.x * l.x + n.y * l.y + n.z * l.z);
        sum.x += c.x * nl;
        sum.y += c.y * nl;
        sum.z += c.z * nl;
    }
    return sum;
}

inline simd::vec3x8 specular_term(const LightSet& lights, const simd::vec3x8& n, const simd::vec3x8& to_eye,
                                  const glm::vec3& specular, float shininess) {
    using simd::splat;
    simd::vec3x8 sum{splat(0.0f), splat(0.0f), splat(0.0f)};
    for (int i = 0; i < lights.count; ++i) {
        const glm::vec3 l = lights.to_light[size_t(i)];
        const glm::vec3 k = lights.color[size_t(i)] * specular;
        const simd::i8 lit = (n.x * l.x + n.y * l.y + n.z * l.z) > 0.0f;
        if (!simd::any(lit)) continue;
        const simd::vec3x8 h{to_eye.x + l.x, to_eye.y + l.y, to_eye.z + l.z};
        const simd::f8 nh = simd::dot(n, h) / simd::sqrt(simd::dot(h, h));  // N . normalize(H)
        const simd::f8 p = simd::select(lit, specular_power(simd::max(splat(0.0f), nh), shininess), splat(0.0f));
        sum.x += k.x * p;
        sum.y += k.y * p;
        sum.z += k.z * p;
    }
    return sum;
}

}  // namespace softraster
