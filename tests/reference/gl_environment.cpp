#include "gl_environment.h"
#include "gl_shaders.h"

#include <array>
#include <cstddef>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

namespace glref {

namespace {

const char* const kSkyVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_clip;
layout(location = 1) in vec3 a_direction;
out vec3 v_direction;
void main() {
    v_direction = a_direction;
    gl_Position = vec4(a_clip.x, -a_clip.y, a_clip.z, a_clip.w);  // row 0 at the top, as the scene's
}
)";
const char* const kSkyFragmentShader = R"(#version 330 core
in vec3 v_direction;
uniform sampler2D u_sky;
uniform float u_intensity;
uniform int u_tone;        // -1: none; else the curve: 0 none, 1 Reinhard, 2 ACES
uniform float u_exposure;
out vec4 frag;
void main() {
    vec3 d = normalize(v_direction);
    vec2 uv = vec2(0.5 + atan(d.x, -d.z) * 0.159154943091895, acos(clamp(d.y, -1.0, 1.0)) * 0.318309886183791);
    vec3 c = texture(u_sky, uv).rgb * u_intensity;
    if (u_tone >= 0) {
        vec3 x = u_exposure * c;
        if (u_tone == 1) x = x / (1.0 + x);
        if (u_tone == 2) x = clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
        c = x;
    }
    frag = vec4(c, 1.0);
}
)";

}  // namespace

GlEnvironment::GlEnvironment(const softraster::EnvironmentLighting* e, const glm::mat4& view, const glm::mat4& projection,
                             const softraster::ToneMapping& tone)
    : env_(e), tone_(tone) {
    if (!env_) return;
    if (env_->background) {
        sky_program_ = standalone_program(kSkyVertexShader, kSkyFragmentShader, "sky");
        glGenTextures(1, &sky_texture_);
        glBindTexture(GL_TEXTURE_2D, sky_texture_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, env_->picture.width, env_->picture.height, 0, GL_RGB, GL_FLOAT, env_->picture.texels.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        const std::array<softraster::SkyVertex, 3> v = softraster::sky_triangle(view, projection);
        glGenVertexArrays(1, &sky_vao_);
        glBindVertexArray(sky_vao_);
        glGenBuffers(1, &sky_vbo_);
        glBindBuffer(GL_ARRAY_BUFFER, sky_vbo_);
        glBufferData(GL_ARRAY_BUFFER, sizeof v, v.data(), GL_STATIC_DRAW);
        glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(softraster::SkyVertex), reinterpret_cast<void*>(offsetof(softraster::SkyVertex, clip)));
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(softraster::SkyVertex),
                              reinterpret_cast<void*>(offsetof(softraster::SkyVertex, direction)));
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
    }
    using softraster::EnvironmentLighting;
    glGenTextures(1, &specular_);
    glBindTexture(GL_TEXTURE_2D, specular_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int k = 0; k < EnvironmentLighting::kLevels; ++k) {  // row 0 first: t = 0 is the top, as v
        const softraster::EquirectView m = env_->specular_level(k);
        glTexImage2D(GL_TEXTURE_2D, k, GL_RGB32F, m.width, m.height, 0, GL_RGB, GL_FLOAT, m.texels);
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
    glDeleteTextures(1, &sky_texture_);
    glDeleteBuffers(1, &sky_vbo_);
    glDeleteVertexArrays(1, &sky_vao_);
    if (sky_program_) glDeleteProgram(sky_program_);
}

void GlEnvironment::draw_sky() const {
    if (!sky_program_) return;
    glUseProgram(sky_program_);
    glUniform1i(glGetUniformLocation(sky_program_, "u_sky"), 0);
    glUniform1f(glGetUniformLocation(sky_program_, "u_intensity"), env_->intensity);
    glUniform1i(glGetUniformLocation(sky_program_, "u_tone"), tone_.active() ? int(tone_.curve) : -1);
    glUniform1f(glGetUniformLocation(sky_program_, "u_exposure"), tone_.exposure);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sky_texture_);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glBindVertexArray(sky_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
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
