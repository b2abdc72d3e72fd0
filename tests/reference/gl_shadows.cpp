#include "gl_shadows.h"
#include "gl_shaders.h"
#include "gl_state.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace glref {

GlShadows::GlShadows(const softraster::Scene& scene) {
    const softraster::Bounds bounds = softraster::shadow_bounds(scene);
    // A map of `faces` layers; face f seen through matrix(f), biased along travel(f).
    auto add = [&](const softraster::ShadowSettings& s, int faces, auto&& matrix, auto&& travel) {
        Map m;
        m.settings = s;
        glGenTextures(1, &m.texture);
        glBindTexture(GL_TEXTURE_2D_ARRAY, m.texture);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, s.size, s.size, faces, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        for (int f = 0; f < faces; ++f) {
            Face face;
            face.matrix = matrix(f);
            face.offset = softraster::shadow_offset(s, travel(f));
            glGenFramebuffers(1, &face.fbo);
            glBindFramebuffer(GL_FRAMEBUFFER, face.fbo);
            glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, m.texture, 0, f);
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
            if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("shadow map framebuffer incomplete");
            m.faces.push_back(face);
        }
        maps_.push_back(m);
        return int(maps_.size()) - 1;
    };
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    for (const softraster::DirectionalLight& l : scene.lights.directional)
        directional_.push_back(
            l.shadow ? add(*l.shadow, 1, [&](int) { return softraster::shadow_matrix(l, bounds); }, [&](int) { return l.direction; })
                     : -1);
    for (const softraster::PunctualLight& l : scene.lights.punctual) {
        if (!l.shadow) punctual_.push_back(-1);
        else if (l.spot)
            punctual_.push_back(add(*l.shadow, 1, [&](int) { return softraster::shadow_matrix(l, bounds); }, [&](int) { return l.direction; }));
        else {
            punctual_.push_back(add(*l.shadow, 6, [&](int f) { return softraster::shadow_matrix(l, bounds, f); }, softraster::cube_face_axis));
            maps_.back().light = l.position;
        }
    }
    for (std::vector<int>* list : {&directional_, &punctual_})
        for (int& k : *list)
            if (k < 0) k = count();
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    if (!maps_.empty()) program_ = standalone_program(kDepthVertexShader, kDepthFragmentShader, "depth pass");
}

GlShadows::~GlShadows() {
    for (const Map& m : maps_) {
        for (const Face& f : m.faces) glDeleteFramebuffers(1, &f.fbo);
        glDeleteTextures(1, &m.texture);
    }
    if (program_) glDeleteProgram(program_);
}

std::string GlShadows::defines() const { return "#define SHADOWS " + std::to_string(count()) + "\n"; }

void GlShadows::draw(const std::vector<Caster>& casters) const {
    if (maps_.empty()) return;
    glUseProgram(program_);
    glDisable(GL_CULL_FACE);  // both faces cast
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    for (const Map& m : maps_)
        for (const Face& f : m.faces) {
            const PassTarget target(f.fbo, m.settings.size, m.settings.size);
            glClearDepth(1.0);
            glClear(GL_DEPTH_BUFFER_BIT);
            glPolygonOffset(m.settings.slope_bias, 0.0f);
            for (const Caster& c : casters) {
                const glm::mat4 mvp = glm::mat4(glm::dmat4(f.matrix) * glm::dmat4(c.model));
                glUniformMatrix4fv(glGetUniformLocation(program_, "u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
                glBindVertexArray(c.vao);
                glDrawElements(GL_TRIANGLES, c.index_count, GL_UNSIGNED_INT, nullptr);
            }
        }
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void GlShadows::bind(GLuint program) const {
    // name[index] (appended piece by piece: g++ 12 warns falsely on "a" + std::string + "b")
    auto loc = [&](const char* name, size_t index) {
        std::string n = name;
        n += '[';
        n += std::to_string(index);
        n += ']';
        return glGetUniformLocation(program, n.c_str());
    };
    for (size_t i = 0; i < directional_.size(); ++i) glUniform1i(loc("u_shadow_of", i), directional_[i]);
    for (size_t i = 0; i < punctual_.size(); ++i) glUniform1i(loc("u_pl_shadow", i), punctual_[i]);
    for (size_t s = 0; s < maps_.size(); ++s) {
        const Map& m = maps_[s];
        for (size_t f = 0; f < m.faces.size(); ++f) {
            glUniformMatrix4fv(loc("u_shadow_matrix", s * 6 + f), 1, GL_FALSE, glm::value_ptr(m.faces[f].matrix));
            glUniform3fv(loc("u_shadow_offset", s * 6 + f), 1, glm::value_ptr(m.faces[f].offset));
        }
        glUniform1i(loc("u_shadow_faces", s), int(m.faces.size()));
        glUniform3fv(loc("u_shadow_light", s), 1, glm::value_ptr(m.light));
        glUniform1i(loc("u_shadow_size", s), m.settings.size);
        glUniform1i(loc("u_shadow_pcf", s), m.settings.pcf);
        const std::string map = "u_shadow_map" + std::to_string(s);
        glUniform1i(glGetUniformLocation(program, map.c_str()), kFirstUnit + int(s));
        glActiveTexture(GLenum(GL_TEXTURE0 + kFirstUnit + int(s)));
        glBindTexture(GL_TEXTURE_2D_ARRAY, m.texture);
    }
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace glref
