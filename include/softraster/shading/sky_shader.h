// The environment as the picture's background (docs/scene-format.md "Environment lighting",
// `background`): one triangle over the whole picture, drawn first, whose corners carry the
// world-space direction of the view ray through them; each pixel shows the environment's
// picture, bilinear, in the interpolated direction.
#pragma once
#include <array>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "softraster/pipeline/shader.h"
#include "softraster/shading/environment_lighting.h"
#include "softraster/shading/tone_mapping.h"

namespace softraster {

struct SkyVertex {
    glm::vec4 clip{0.0f};
    glm::vec3 direction{0.0f};
};

struct SkyVaryings {
    glm::vec3 direction;
};

struct SkyShader {
    using Vertex = SkyVertex;
    using Varyings = SkyVaryings;
    static constexpr bool kPure = true;
    const EquirectImage* picture = nullptr;
    float intensity = 1.0f;
    ToneMapping tone_mapping;

    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.direction = in.direction;
        return in.clip;
    }
    bool fragment(const Varyings& in, const FragCoord&, glm::vec4& out) const {
        out = glm::vec4(sample_bilinear(*picture, equirect_uv(glm::normalize(in.direction))) * intensity, 1.0f);
        if (tone_mapping.active()) out = tone_map(tone_mapping, out);
        return true;
    }
};

// The triangle's corners at clip (-1, -1), (3, -1), (-1, 3) (z 0, w 1), each with the
// direction far - near of the points the inverse of projection * view maps (x, y, +1) and
// (x, y, -1) to, computed in double.
inline std::array<SkyVertex, 3> sky_triangle(const glm::mat4& view, const glm::mat4& projection) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(projection) * glm::dmat4(view));
    std::array<SkyVertex, 3> v;
    const double corners[3][2] = {{-1, -1}, {3, -1}, {-1, 3}};
    for (size_t k = 0; k < 3; ++k) {
        const double x = corners[k][0], y = corners[k][1];
        const glm::dvec4 far = inverse * glm::dvec4(x, y, 1.0, 1.0), near = inverse * glm::dvec4(x, y, -1.0, 1.0);
        v[k].clip = glm::vec4(float(x), float(y), 0.0f, 1.0f);
        v[k].direction = glm::vec3(glm::dvec3(far) / far.w - glm::dvec3(near) / near.w);
    }
    return v;
}

}  // namespace softraster
