// The reference's image-based lighting: softraster's precomputed maps (environment_lighting.h)
// as GL textures, the prefiltered levels as an explicit GL_RGB32F mipmap read with textureLod,
// the split sum's table as GL_RG32F, the spherical harmonics as uniforms; the GLSL is
// environment_light in gl_shaders.cpp.
#pragma once
#include <string>

#include "osmesa_target.h"
#include "softraster/shading/sky_shader.h"

namespace glref {

class GlEnvironment {
public:
    static constexpr int kSpecularUnit = 9, kLutUnit = 10;

    // With a background, the camera's matrices and the tone mapping for the sky.
    GlEnvironment(const softraster::EnvironmentLighting* e, const glm::mat4& view, const glm::mat4& projection,
                  const softraster::ToneMapping& tone);
    ~GlEnvironment();
    GlEnvironment(const GlEnvironment&) = delete;
    GlEnvironment& operator=(const GlEnvironment&) = delete;

    std::string defines() const { return std::string("#define ENVIRONMENT ") + (env_ ? "1" : "0") + "\n"; }
    void bind(GLuint program) const;
    // The sky triangle (sky_shader.h), right after the clear: no depth, no culling, no blending.
    void draw_sky() const;

private:
    const softraster::EnvironmentLighting* env_;
    GLuint specular_ = 0, lut_ = 0;
    GLuint sky_program_ = 0, sky_texture_ = 0, sky_vao_ = 0, sky_vbo_ = 0;
    softraster::ToneMapping tone_;
};

}  // namespace glref
