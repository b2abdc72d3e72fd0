// Lesson 16: normal mapping (法线贴图). A texture whose texels are normals, in the surface's
// own frame (tangent space, 切线空间), bends the light per pixel as if the surface had bumps
// that its triangles do not have.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "../12-textures/texture.h"
#include "softraster/context.h"
#include "softraster/scene/mesh.h"

namespace course {

// A normal map of round bumps, 4 x 4 per texture: the height of each bump is a dome, and the
// normal of a height field h(u, v) is normalize(-dh/du, -dh/dv, 1). Stored as (n + 1) / 2 in
// 8 bits per channel, the usual encoding (the blue-violet color of normal maps: flat is
// (0.5, 0.5, 1)).
inline TexelImage bumps_normal_map(int size) {
    TexelImage t{size, size, {}};
    const float cell = float(size) / 4.0f;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            // Within its cell, the texel's offset from the bump's center, -1..1.
            const float x = (std::fmod(float(i) + 0.5f, cell) / cell) * 2.0f - 1.0f, y = (std::fmod(float(j) + 0.5f, cell) / cell) * 2.0f - 1.0f;
            const float r2 = x * x + y * y;
            glm::vec3 n(0, 0, 1);
            if (r2 < 0.64f) {  // a dome of radius 0.8: h = sqrt(0.64 - r^2), slopes -x/h, -y/h (scaled down by 2)
                const float h = std::sqrt(0.64f - r2);
                n = glm::normalize(glm::vec3(0.5f * x / std::max(h, 0.2f), 0.5f * y / std::max(h, 0.2f), 1.0f));
            }
            t.texels.push_back(glm::u8vec4(glm::round((n * 0.5f + 0.5f) * 255.0f), 255));
        }
    return t;
}

// The map's normal m = 2 texel - 1, turned from tangent space into the world with the TBN
// matrix (TBN 矩阵): its x along the tangent T (the direction of +u on the surface), y along
// the bitangent B = w cross(N, T) (+v; w says which way round the texture is glued), z along
// the normal N: n = normalize(m.x T + m.y B + m.z N).
inline glm::vec3 perturbed_normal(const glm::vec3& N, const glm::vec4& T, const glm::vec3& texel) {
    const glm::vec3 t(T), b = T.w * glm::cross(N, t), m = texel * 2.0f - 1.0f;
    return glm::normalize(m.x * t + m.y * b + m.z * N);
}

struct BumpVaryings {
    glm::vec3 normal, position;
    glm::vec4 tangent;
    glm::vec2 uv;
};

// Lambert and a Blinn-Phong highlight (lesson 11) with the normal from the map, or the
// surface's own where `map` is null.
struct NormalMappedShader {
    using Vertex = softraster::TangentVertex;
    using Varyings = BumpVaryings;
    glm::mat4 model, view_projection;
    glm::vec3 eye, to_light, albedo;
    const TexelImage* map;
    float repeats;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        const glm::vec4 world = model * glm::vec4(in.position, 1.0f);
        out = {glm::mat3(model) * in.normal, glm::vec3(world), glm::vec4(glm::mat3(model) * glm::vec3(in.tangent), in.tangent.w), in.uv};
        return view_projection * world;
    }
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& color) const {
        const glm::vec3 n = map ? perturbed_normal(in.normal, in.tangent, glm::vec3(sample_bilinear(*map, in.uv * repeats)))
                                : glm::normalize(in.normal);
        const float diffuse = std::max(0.0f, glm::dot(n, to_light));
        const float spec = diffuse > 0.0f ? std::pow(std::max(0.0f, glm::dot(n, glm::normalize(to_light + glm::normalize(eye - in.position)))), 60.0f) : 0.0f;
        color = glm::vec4(glm::min(albedo * (0.15f + 0.85f * diffuse) + glm::vec3(0.35f * spec), glm::vec3(1.0f)), 1.0f);
        return true;
    }
};

}  // namespace course
