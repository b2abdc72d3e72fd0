// Shadow maps (docs/scene-format.md "Shadows"): the depth of the nearest surface seen from a
// light, stored per texel by a depth pass of our own pipeline (scene_renderer.cpp), and the
// test of a surface point P against it with percentage-closer filtering (PCF, Reeves et al.
// 1987): the light reaches P in the share of the (2r+1)^2 texels around P's texel whose
// stored depth is at or beyond P's.
//
//   q = S (P + b, 1)                      S: the light's view-projection, b: the bias offset
//   x = (q.x/q.w + 1) size/2, y = (1 - q.y/q.w) size/2, z = (q.z/q.w + 1)/2
//                                         (the pipeline's window coordinates, viewport.h)
//   visibility = #{ |di|, |dj| <= r : z <= D(clamp(floor x + di), clamp(floor y + dj)) } / (2r+1)^2
//
// and 1 where q.w <= 0 (behind a spot light). Texel indices are clamped to [0, size - 1].
// A point light's map is a cube: six such faces, 90 degrees wide, looking from the light
// along +x, -x, +y, -y, +z, -z. P is looked up in the face of the major axis of P - light
// (as a GL cube map chooses its face), with that face's S and b; the kernel stays inside the
// face (its indices clamp at the edges like any map's).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

struct ShadowFace {
    const float* depth = nullptr;  // size x size window depths, row 0 at the top
    glm::mat4 matrix{1.0f};        // S: world space to the light's clip space
    glm::vec3 offset{0.0f};        // b: bias times the unit vector toward the light
};

struct ShadowMap {
    std::array<ShadowFace, 6> face{};
    int faces = 1;              // 1, or 6: a point light's cube, faces in the order +x, -x, +y, -y, +z, -z
    glm::vec3 light{0.0f};      // a cube's center: the light's position
    int size = 0;
    int pcf = 1;                // r: the kernel is (2r+1) x (2r+1) texels
};

// The face of a cube that P falls in: the major axis of d = P - light, x before y before z
// where their magnitudes tie, + where d's component is >= 0.
inline int cube_face(const ShadowMap& m, float px, float py, float pz) {
    const float dx = px - m.light.x, dy = py - m.light.y, dz = pz - m.light.z;
    const float ax = std::abs(dx), ay = std::abs(dy), az = std::abs(dz);
    if (ax >= ay && ax >= az) return dx >= 0.0f ? 0 : 1;
    if (ay >= az) return dy >= 0.0f ? 2 : 3;
    return dz >= 0.0f ? 4 : 5;
}

// The numbers a lookup needs: where P falls in the map, in window coordinates, and q.w.
template <class T>
struct ShadowCoords {
    T x, y, z, w;
};

// The same operations for one point (float) and eight (simd::f8), so both give the same
// bits. (Results by reference: a 32-byte vector passed by value may cross the AVX2 and
// generic copies' different calling conventions.)
template <class T>
void shadow_coords(const ShadowFace& f, int size, const T& px0, const T& py0, const T& pz0, ShadowCoords<T>& c) {
    const T px = px0 + f.offset.x, py = py0 + f.offset.y, pz = pz0 + f.offset.z;
    const glm::mat4& s = f.matrix;
    const T qx = s[0][0] * px + s[1][0] * py + s[2][0] * pz + s[3][0];
    const T qy = s[0][1] * px + s[1][1] * py + s[2][1] * pz + s[3][1];
    const T qz = s[0][2] * px + s[1][2] * py + s[2][2] * pz + s[3][2];
    const T qw = s[0][3] * px + s[1][3] * py + s[2][3] * pz + s[3][3];
    const T inv_w = 1.0f / qw;
    const float half = 0.5f * float(size);
    c.x = (qx * inv_w + 1.0f) * half;
    c.y = (1.0f - qy * inv_w) * half;
    c.z = (qz * inv_w + 1.0f) * 0.5f;
    c.w = qw;
}

// The PCF count at one point: how many kernel texels hold a depth >= z.
inline int shadow_lit_texels(const ShadowMap& m, const ShadowFace& f, float x, float y, float z) {
    const int last = m.size - 1;
    // floor, clamped: the clamp to [-1, size] first keeps the conversion in range (and NaN out).
    const int i = std::clamp(int(std::floor(std::clamp(x, -1.0f, float(m.size)))), 0, last);
    const int j = std::clamp(int(std::floor(std::clamp(y, -1.0f, float(m.size)))), 0, last);
    int lit = 0;
    for (int dj = -m.pcf; dj <= m.pcf; ++dj) {
        const float* row = f.depth + size_t(std::clamp(j + dj, 0, last)) * size_t(m.size);
        for (int di = -m.pcf; di <= m.pcf; ++di) lit += z <= row[std::clamp(i + di, 0, last)];
    }
    return lit;
}

inline float shadow_kernel_share(const ShadowMap& m) { return 1.0f / float((2 * m.pcf + 1) * (2 * m.pcf + 1)); }

inline void shadow_visibility(const ShadowMap& m, const glm::vec3& p, float& v) {
    const ShadowFace& f = m.face[size_t(m.faces == 1 ? 0 : cube_face(m, p.x, p.y, p.z))];
    ShadowCoords<float> c;
    shadow_coords(f, m.size, p.x, p.y, p.z, c);
    v = c.w > 0.0f ? float(shadow_lit_texels(m, f, c.x, c.y, c.z)) * shadow_kernel_share(m) : 1.0f;
}

inline void shadow_visibility(const ShadowMap& m, const simd::vec3x8& p, simd::f8& v) {
    if (m.faces != 1) {  // a cube: each lane in its own face, one at a time
        for (int l = 0; l < simd::kLanes; ++l) {
            float lane;
            shadow_visibility(m, glm::vec3(p.x[l], p.y[l], p.z[l]), lane);
            v[l] = lane;
        }
        return;
    }
    const ShadowFace& f = m.face[0];
    ShadowCoords<simd::f8> c;
    shadow_coords(f, m.size, p.x, p.y, p.z, c);
    const float share = shadow_kernel_share(m);
    for (int l = 0; l < simd::kLanes; ++l) v[l] = c.w[l] > 0.0f ? float(shadow_lit_texels(m, f, c.x[l], c.y[l], c.z[l])) * share : 1.0f;
}

// The visibility of each shadowed light of a set at a point; the last entry, 1, stands for
// the lights without a shadow.
inline constexpr int kMaxShadowedLights = 4;
template <class T>
using LightVisibility = std::array<T, kMaxShadowedLights + 1>;

}  // namespace softraster
