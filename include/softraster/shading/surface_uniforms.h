// What the scene's surface shader (surface_shader.h) reads that is the same for all the
// vertices and fragments of one draw: matrices, lights and the material.
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "softraster/shading/environment_lighting.h"
#include "softraster/shading/lighting.h"
#include "softraster/shading/texture.h"
#include "softraster/shading/tone_mapping.h"

namespace softraster {

// Everything a draw's shader reads that is the same for all its vertices and fragments.
struct SurfaceUniforms {
    glm::mat4 mvp{1.0f};
    glm::mat4 model{1.0f};
    glm::mat3 normal_matrix{1.0f};  // transpose(inverse(mat3(M))); identity for pre-transformed normals
    glm::vec3 eye{0.0f};
    LightSet lights;
    glm::vec4 color{1.0f};
    glm::vec3 specular{0.0f};
    bool has_specular = false;  // specular != 0: otherwise the term is skipped
    float shininess = 32.0f;
    const Texture* texture = nullptr;
    Sampler sampler;
    // pbr (pbr.h): the factors and the maps, sampled with the same sampler and uv.
    float metallic = 0.0f, roughness = 0.5f;
    glm::vec3 emissive{0.0f};
    float occlusion_strength = 1.0f;
    const Texture* metallic_roughness_texture = nullptr;
    const Texture* occlusion_texture = nullptr;
    const Texture* emissive_texture = nullptr;
    const Texture* normal_texture = nullptr;  // with it the draw's mesh carries tangents (normal_mapping.h)
    float normal_scale = 1.0f;
    const EnvironmentLighting* environment = nullptr;  // pbr: image-based lighting (environment_lighting.h)
    ToneMapping tone_mapping;  // exposure and tone curve, the shader's last step (not for normals and depth)
};

}  // namespace softraster
