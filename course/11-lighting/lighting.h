// Lesson 11: lighting models. All vectors unit length: n the surface normal, l towards the
// light, v towards the eye.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "../10-shaders/shaders.h"

namespace course {

// Diffuse (漫反射), lesson 4's Lambert: light scattered equally in all directions.
inline float diffuse(const glm::vec3& n, const glm::vec3& l) { return std::max(0.0f, glm::dot(n, l)); }

// Phong's specular highlight (镜面高光, Phong 1975): mirror l about n, r = 2 (n.l) n - l, and
// measure how close r comes to the eye: (r.v)^s. The larger the shininess s, the smaller and
// sharper the highlight.
inline float specular_phong(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float s) {
    const glm::vec3 r = 2.0f * glm::dot(n, l) * n - l;
    return std::pow(std::max(0.0f, glm::dot(r, v)), s);
}

// Blinn-Phong (Blinn 1977): the half vector h = normalize(l + v), halfway between light and
// eye, and how close the normal comes to it: (n.h)^s. Cheaper (no reflection), and it keeps a
// sensible highlight at grazing angles where r.v collapses; for a similar highlight take
// about four times Phong's s.
inline float specular_blinn_phong(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float s) {
    return std::pow(std::max(0.0f, glm::dot(n, glm::normalize(l + v))), s);
}

enum class Model { Gouraud, Phong, BlinnPhong };

// Ambient + diffuse + specular (the Phong reflection model), with a white light. No highlight
// where the light does not reach the surface (n.l <= 0).
inline glm::vec3 reflect_light(Model m, const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, const glm::vec3& albedo) {
    const float spec = glm::dot(n, l) <= 0.0f      ? 0.0f
                       : m == Model::BlinnPhong ? specular_blinn_phong(n, l, v, 4.0f * 24.0f)
                                                : specular_phong(n, l, v, 24.0f);
    return albedo * (0.12f + 0.88f * diffuse(n, l)) + glm::vec3(0.6f * spec);
}

struct LitVaryings {
    glm::vec3 normal, position, color;  // color: Gouraud's, lit at the vertex
};

// Gouraud shading (高洛德着色): light each *vertex* and interpolate the colors. Phong shading
// (冯氏着色): interpolate the *normal* and light each pixel. (Phong's name is on both the
// shading and the highlight formula; they are different ideas.)
template <Model M>
struct LitShader {
    using Vertex = MeshIn;
    using Varyings = LitVaryings;
    glm::mat4 model, view_projection;
    glm::vec3 eye, light_position, albedo;

    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.position = glm::vec3(model * glm::vec4(in.position, 1.0f));
        out.normal = glm::mat3(model) * in.normal;
        if constexpr (M == Model::Gouraud) {
            const glm::vec3 n = glm::normalize(out.normal);
            out.color = reflect_light(M, n, glm::normalize(light_position - out.position), glm::normalize(eye - out.position), albedo);
        } else {
            out.color = glm::vec3(0.0f);
        }
        return view_projection * glm::vec4(out.position, 1.0f);
    }
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& color) const {
        if constexpr (M == Model::Gouraud) {
            color = glm::vec4(in.color, 1.0f);
        } else {
            const glm::vec3 n = glm::normalize(in.normal);
            color = glm::vec4(reflect_light(M, n, glm::normalize(light_position - in.position), glm::normalize(eye - in.position), albedo), 1.0f);
        }
        color = glm::min(color, glm::vec4(1.0f));
        return true;
    }
};

}  // namespace course
