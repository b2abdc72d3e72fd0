// Small pieces of GL state the reference's passes share.
#pragma once
#include "osmesa_target.h"
#include "softraster/render_state.h"

namespace glref {

// Face culling as softraster's state says. The scene's vertex shaders flip y (row 0 at the
// top of the picture), which mirrors windings: front faces flip too.
inline void set_faces(softraster::CullMode cull, softraster::FrontFace front_face) {
    if (cull == softraster::CullMode::None) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(cull == softraster::CullMode::Back ? GL_BACK : GL_FRONT);
    }
    glFrontFace(front_face == softraster::FrontFace::CCW ? GL_CW : GL_CCW);
}

// Binds `fbo` with a width x height viewport for a pass, and puts back the framebuffer and
// viewport that were bound when it goes out of scope.
class PassTarget {
public:
    PassTarget(GLuint fbo, int width, int height) {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
    }
    ~PassTarget() {
        glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    }
    PassTarget(const PassTarget&) = delete;
    PassTarget& operator=(const PassTarget&) = delete;

private:
    GLint previous_ = 0, viewport_[4] = {};
};

}  // namespace glref
