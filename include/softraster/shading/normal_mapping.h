// Tangent-space normal mapping (docs/scene-format.md "Normal maps").
//
// A normal map's texel (r, g, b) holds a normal m = 2 (r, g, b) − 1 in the surface's frame:
// x along the tangent T (+u), y along the bitangent B (+v), z along the normal N. glTF's
// normal scale multiplies x and y. The world-space normal is then
//   n = normalize(m.x T + m.y B + m.z N),   B = w · cross(N, T)
// with N and T as interpolated, not normalized first: MikkTSpace's pixel-shader form, under
// which the frame matches the one its tangents were generated in (mesh_tangents.cpp).
#pragma once
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

// normal: N; tangent: T in xyz, w in w; texel: the map's lookup in [0, 1].
inline glm::vec3 mapped_normal(const glm::vec3& normal, const glm::vec4& tangent, const glm::vec3& texel, float scale) {
    const glm::vec3 t(tangent);
    const glm::vec3 b = tangent.w * glm::cross(normal, t);
    const float x = (texel.x * 2.0f - 1.0f) * scale, y = (texel.y * 2.0f - 1.0f) * scale, z = texel.z * 2.0f - 1.0f;
    return glm::normalize(x * t + y * b + z * normal);
}

// Eight at once, with the same arithmetic lane by lane.
inline simd::vec3x8 mapped_normal(const simd::vec3x8& n, const simd::vec3x8& t, simd::f8 w, const simd::vec3x8& texel, float scale) {
    using simd::f8;
    const simd::vec3x8 b{w * (n.y * t.z - t.y * n.z), w * (n.z * t.x - t.z * n.x), w * (n.x * t.y - t.x * n.y)};
    const f8 x = (texel.x * 2.0f - 1.0f) * scale, y = (texel.y * 2.0f - 1.0f) * scale, z = texel.z * 2.0f - 1.0f;
    return simd::normalize({x * t.x + y * b.x + z * n.x, x * t.y + y * b.y + z * n.y, x * t.z + y * b.z + z * n.z});
}

}  // namespace softraster
