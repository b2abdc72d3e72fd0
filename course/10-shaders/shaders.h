// Lesson 10: shaders and varyings on softraster's own pipeline (include/softraster/context.h).
// A shader is a plain struct: the vertex type it reads, the varyings it hands from its
// vertex stage to its fragment stage, and the two functions.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "softraster/context.h"
#include "softraster/scene/mesh.h"

namespace course {

// The mesh's vertices as the pipeline reads them: position, normal and color.
struct MeshIn {
    glm::vec3 position, normal;
    glm::vec4 color;
};

// Varyings (插值变量): what the vertex shader writes at each corner and the pipeline
// interpolates, perspective-correctly (lesson 9), to every pixel for the fragment shader.
struct SurfaceVaryings {
    glm::vec3 normal;  // in world space
    glm::vec3 local;   // the model-space position
    glm::vec4 color;
};

enum class Look { VertexColor, Normals, Stripes, Toon };

template <Look L>
struct LessonShader {
    using Vertex = MeshIn;
    using Varyings = SurfaceVaryings;
    glm::mat4 model, view_projection;

    // The vertex shader (顶点着色器): once per corner. It must return the clip-space position
    // (lesson 6), and fills the varyings.
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.normal = glm::mat3(model) * in.normal;  // (no scaling in this lesson's model matrices)
        out.local = in.position;
        out.color = in.color;
        return view_projection * model * glm::vec4(in.position, 1.0f);
    }

    // The fragment shader (片元着色器): once per covered pixel, with the interpolated
    // varyings. Returns false to discard the pixel.
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& color) const {
        const glm::vec3 n = glm::normalize(in.normal);
        const float lambert = std::max(0.0f, glm::dot(n, glm::normalize(glm::vec3(-0.4f, 0.8f, 0.6f))));
        if constexpr (L == Look::VertexColor) {
            color = in.color;
        } else if constexpr (L == Look::Normals) {
            color = glm::vec4(0.5f * n + 0.5f, 1.0f);  // the normal's x, y, z as red, green, blue
        } else if constexpr (L == Look::Stripes) {
            const bool stripe = std::fmod(std::fabs(in.local.y) * 10.0f, 1.0f) < 0.5f;  // bands in model space
            color = glm::vec4((stripe ? glm::vec3(0.9f, 0.3f, 0.25f) : glm::vec3(0.95f)) * (0.2f + 0.8f * lambert), 1.0f);
        } else {
            const float band = std::floor(lambert * 3.0f + 0.5f) / 3.0f;  // three tones: "toon" shading
            color = glm::vec4(glm::vec3(0.3f, 0.6f, 0.95f) * (0.25f + 0.75f * band), 1.0f);
        }
        return true;
    }
};

inline std::vector<MeshIn> mesh_vertices(const softraster::Mesh& mesh) {
    std::vector<MeshIn> out;
    for (const softraster::MeshVertex& v : mesh.vertices) out.push_back({v.position, v.normal, v.color});
    return out;
}

}  // namespace course
