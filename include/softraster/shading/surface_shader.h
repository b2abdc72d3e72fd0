// The scene format's seven shading models as one shader template (spec "Shading").
//
// SurfaceShader<Model, Textured> is a Shader (pipeline/shader.h): the model and whether a
// texture is sampled are template arguments, so each combination's fragment code is compiled
// on its own with no per-pixel branch on the shading model.
#pragma once
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "softraster/pipeline/shader.h"
#include "softraster/scene/mesh.h"
#include "softraster/scene/scene.h"
#include "softraster/shading/lighting.h"
#include "softraster/shading/texture.h"

namespace softraster {

struct SurfaceVaryings {
    glm::vec3 world;      // world-space position P
    glm::vec3 normal;     // world-space normal, normalized per fragment
    glm::vec2 uv;
    glm::vec4 color;      // vertex color
    glm::vec3 intensity;  // Gouraud: lighting computed at the vertex
};

// Everything a draw's shader reads that is the same for all its vertices and fragments.
struct SurfaceUniforms {
    glm::mat4 mvp{1.0f};
    glm::mat4 model{1.0f};
    glm::mat3 normal_matrix{1.0f};  // transpose(inverse(mat3(M))); identity for pre-transformed normals
    glm::vec3 eye{0.0f};
    LightSet lights;
    glm::vec4 color{1.0f};
    glm::vec3 specular{0.0f};
    float shininess = 32.0f;
    const Texture* texture = nullptr;
    Filter filter = Filter::Bilinear;
    Wrap wrap = Wrap::Repeat;
};

template <Shading Model, bool Textured>
struct SurfaceShader {
    using Vertex = MeshVertex;
    using Varyings = SurfaceVaryings;
    const SurfaceUniforms* u;

    glm::vec4 vertex(const MeshVertex& in, SurfaceVaryings& out) const {
        const glm::vec4 world = u->model * glm::vec4(in.position, 1.0f);
        out.world = glm::vec3(world);
        out.normal = u->normal_matrix * in.normal;
        out.uv = in.uv;
        out.color = in.color;
        if constexpr (Model == Shading::Gouraud) out.intensity = diffuse_intensity(u->lights, glm::normalize(out.normal));
        else out.intensity = glm::vec3(0.0f);
        return u->mvp * glm::vec4(in.position, 1.0f);
    }

    bool fragment(const SurfaceVaryings& in, const FragCoord& frag, glm::vec4& out) const {
        if constexpr (Model == Shading::Depth) {
            out = glm::vec4(frag.z, frag.z, frag.z, 1.0f);
            return true;
        }
        const glm::vec3 n = glm::normalize(in.normal);
        if constexpr (Model == Shading::Normals) {
            out = glm::vec4(0.5f * n + 0.5f, 1.0f);
            return true;
        }
        glm::vec4 base = u->color * in.color;
        if constexpr (Textured) base *= u->texture->sample(in.uv, u->filter, u->wrap);
        if constexpr (Model == Shading::Unlit) {
            out = base;
        } else if constexpr (Model == Shading::Gouraud) {
            out = glm::vec4(glm::vec3(base) * in.intensity, base.a);
        } else {  // Lambert, Flat (N is the face normal), BlinnPhong
            glm::vec3 rgb = glm::vec3(base) * diffuse_intensity(u->lights, n);
            if constexpr (Model == Shading::BlinnPhong)
                rgb += specular_term(u->lights, n, glm::normalize(u->eye - in.world), u->specular, u->shininess);
            out = glm::vec4(rgb, base.a);
        }
        return true;
    }
};

}  // namespace softraster
