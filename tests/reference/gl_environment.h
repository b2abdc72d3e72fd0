// The reference's image-based lighting: softraster's precomputed maps (environment_lighting.h)
// as GL textures, the prefiltered levels as an explicit GL_RGB32F mipmap read with textureLod,
// the split sum's table as GL_RG32F, the spherical harmonics as uniforms; the GLSL is
// environment_light in gl_shaders.cpp.
#pragma once
#include <string>

#include "osmesa_target.h"
#include "softraster/shading/environment_lighting.h"

namespace glref {

class GlEnvironment {
public:
    static constexpr int kSpecularUnit = 9, kLutUnit = 10;

    explicit GlEnvironment(const softraster::EnvironmentLighting* e);
    ~GlEnvironment();
    GlEnvironment(const GlEnvironment&) = delete;
    GlEnvironment& operator=(const GlEnvironment&) = delete;

    std::string defines() const { return std::string("#define ENVIRONMENT ") + (env_ ? "1" : "0") + "\n"; }
    void bind(GLuint program) const;

private:
    const softraster::EnvironmentLighting* env_;
    GLuint specular_ = 0, lut_ = 0;
};

}  // namespace glref
