#include "gl_ambient_occlusion.h"
#include "gl_shaders.h"
#include "gl_state.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace glref {
namespace {

const char* const kFullScreenVertexShader = R"(#version 330 core
void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";

// The spec's formula, term for term in the same order as softraster's ambient_occlusion.cpp.
// Window row r holds picture row r (the scene's vertex shaders flip y).
const char* const kOcclusionFragmentShader = R"(#version 330 core
uniform sampler2D u_depth;
uniform mat4 u_inverse;
uniform mat4 u_projection;
uniform ivec2 u_size;
uniform float u_radius, u_intensity, u_bias;
uniform vec2 u_kernel[16];
layout(location = 0) out vec4 o_ao;

vec3 position(ivec2 q) {
    float d = texelFetch(u_depth, q, 0).r;
    float nx = 2.0 * (float(q.x) + 0.5) / float(u_size.x) - 1.0;
    float ny = 1.0 - 2.0 * (float(q.y) + 0.5) / float(u_size.y);
    float nz = 2.0 * d - 1.0;
    vec4 c;
    for (int j = 0; j < 4; ++j) c[j] = u_inverse[0][j] * nx + u_inverse[1][j] * ny + u_inverse[2][j] * nz + u_inverse[3][j];
    return vec3(c.x / c.w, c.y / c.w, c.z / c.w);
}

vec3 tangent(vec3 p, bool has_before, bool has_after, ivec2 before, ivec2 after) {
    if (!has_after) return has_before ? p - position(before) : vec3(0.0);
    vec3 a = position(after) - p;
    if (!has_before) return a;
    vec3 b = p - position(before);
    return abs(a.z) < abs(b.z) ? a : b;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_ao = vec4(1.0);
    if (!(texelFetch(u_depth, p, 0).r < 1.0)) return;
    vec3 P = position(p);
    vec3 tx = tangent(P, p.x > 0, p.x + 1 < u_size.x, p - ivec2(1, 0), p + ivec2(1, 0));
    vec3 ty = tangent(P, p.y > 0, p.y + 1 < u_size.y, p - ivec2(0, 1), p + ivec2(0, 1));
    vec3 n = cross(tx, ty);
    float len = sqrt(dot(n, n));
    if (!(len > 0.0)) return;
    n = n / len;
    if (dot(n, P) > 0.0) n = -n;
    float w = u_projection[0][3] * P.x + u_projection[1][3] * P.y + u_projection[2][3] * P.z + u_projection[3][3];
    float scale = u_radius * (u_projection[1][1] * float(u_size.y) * 0.5 / w);
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        float fx = floor(gl_FragCoord.x + scale * u_kernel[i].x), fy = floor(gl_FragCoord.y + scale * u_kernel[i].y);
        if (!(fx >= 0.0 && fx < float(u_size.x) && fy >= 0.0 && fy < float(u_size.y))) continue;
        ivec2 q = ivec2(fx, fy);
        if (q == p) continue;
        vec3 v = position(q) - P;
        float vv = dot(v, v);
        if (!(vv > 0.0)) continue;
        float rise = dot(n, v) / sqrt(vv) - u_bias;
        float fade = 1.0 - vv / (u_radius * u_radius);
        if (rise > 0.0 && fade > 0.0) sum += rise * fade;
    }
    o_ao = vec4(clamp(1.0 - u_intensity / 16.0 * sum, 0.0, 1.0));
}
)";

GLuint target_texture(GLenum internal, GLenum format, GLenum type, int w, int h) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

GlAmbientOcclusion::GlAmbientOcclusion(const softraster::Scene& scene, int width, int height) : width_(width), height_(height) {
    if (!scene.ambient_occlusion) return;
    settings_ = *scene.ambient_occlusion;
    view_ = softraster::view_matrix(scene.camera);
    projection_ = softraster::projection_matrix(scene.camera, scene.width, scene.height);
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    depth_texture_ = target_texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);
    glGenFramebuffers(1, &depth_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, depth_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture_, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("occlusion depth framebuffer incomplete");
    ao_texture_ = target_texture(GL_R32F, GL_RED, GL_FLOAT, width, height);
    glGenFramebuffers(1, &ao_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, ao_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ao_texture_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("occlusion framebuffer incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    glGenVertexArrays(1, &vao_);
    depth_program_ = standalone_program(kDepthVertexShader, kDepthFragmentShader, "occlusion depth pass");
    program_ = standalone_program(kFullScreenVertexShader, kOcclusionFragmentShader, "ambient occlusion");
}

GlAmbientOcclusion::~GlAmbientOcclusion() {
    if (!program_) return;
    const GLuint fbos[] = {depth_fbo_, ao_fbo_}, textures[] = {depth_texture_, ao_texture_};
    glDeleteFramebuffers(2, fbos);
    glDeleteTextures(2, textures);
    glDeleteVertexArrays(1, &vao_);
    glDeleteProgram(depth_program_);
    glDeleteProgram(program_);
}

void GlAmbientOcclusion::draw_depth(const std::vector<Occluder>& occluders) const {
    if (!program_) return;
    const PassTarget target(depth_fbo_, width_, height_);
    glUseProgram(depth_program_);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    for (const Occluder& o : occluders) {
        set_faces(o.cull, o.front_face);
        const glm::mat4 mvp = glm::mat4(glm::dmat4(projection_) * glm::dmat4(view_) * glm::dmat4(o.model));
        glUniformMatrix4fv(glGetUniformLocation(depth_program_, "u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
        glBindVertexArray(o.vao);
        glDrawElements(GL_TRIANGLES, o.index_count, GL_UNSIGNED_INT, nullptr);
    }
}

std::vector<float> GlAmbientOcclusion::factors() const {
    std::vector<float> out(size_t(width_) * size_t(height_), 1.0f);
    if (!program_) return out;
    const PassTarget target(ao_fbo_, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glUseProgram(program_);
    auto loc = [&](const char* name) { return glGetUniformLocation(program_, name); };
    const glm::mat4 inverse = glm::mat4(glm::inverse(glm::dmat4(projection_)));
    glUniformMatrix4fv(loc("u_inverse"), 1, GL_FALSE, glm::value_ptr(inverse));
    glUniformMatrix4fv(loc("u_projection"), 1, GL_FALSE, glm::value_ptr(projection_));
    glUniform2i(loc("u_size"), width_, height_);
    glUniform1f(loc("u_radius"), settings_.radius);
    glUniform1f(loc("u_intensity"), settings_.intensity);
    glUniform1f(loc("u_bias"), settings_.bias);
    glUniform2fv(loc("u_kernel"), softraster::kAmbientOcclusionSamples, glm::value_ptr(softraster::ambient_occlusion_kernel()[0]));
    glUniform1i(loc("u_depth"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depth_texture_);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ao_fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RED, GL_FLOAT, out.data());
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error in the ambient occlusion pass");
    return out;
}

}  // namespace glref
