#include "gl_environment.h"

#include <glm/gtc/type_ptr.hpp>

namespace glref {

GlEnvironment::GlEnvironment(const softraster::EnvironmentLighting* e) : env_(e) {
    if (!env_) return;
    using softraster::EnvironmentLighting;
    glGenTextures(1, &specular_);
    glBindTexture(GL_TEXTURE_2D, specular_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int k = 0; k < EnvironmentLighting::kLevels; ++k) {  // row 0 first: t = 0 is the top, as v
        const softraster::EquirectImage& m = env_->specular[size_t(k)];
        glTexImage2D(GL_TEXTURE_2D, k, GL_RGB32F, m.width, m.height, 0, GL_RGB, GL_FLOAT, m.texels.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, EnvironmentLighting::kLevels - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenTextures(1, &lut_);
    glBindTexture(GL_TEXTURE_2D, lut_);
    const int n = EnvironmentLighting::kLutSize;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, n, n, 0, GL_RG, GL_FLOAT, env_->lut.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlEnvironment::~GlEnvironment() {
    glDeleteTextures(1, &specular_);
    glDeleteTextures(1, &lut_);
}

void GlEnvironment::bind(GLuint program) const {
    if (!env_) return;
    glUniform3fv(glGetUniformLocation(program, "u_env_sh"), 9, glm::value_ptr(env_->irradiance[0]));
    glUniform1f(glGetUniformLocation(program, "u_env_intensity"), env_->intensity);
    glUniform1i(glGetUniformLocation(program, "u_env_specular"), kSpecularUnit);
    glUniform1i(glGetUniformLocation(program, "u_env_lut"), kLutUnit);
    glActiveTexture(GL_TEXTURE0 + kSpecularUnit);
    glBindTexture(GL_TEXTURE_2D, specular_);
    glActiveTexture(GL_TEXTURE0 + kLutUnit);
    glBindTexture(GL_TEXTURE_2D, lut_);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace glref
