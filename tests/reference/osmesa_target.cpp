#include "osmesa_target.h"

#include <stdexcept>
#include <string>

namespace glref {
namespace {

GLuint make_renderbuffer(GLenum format, int samples, int w, int h) {
    GLuint rb = 0;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    if (samples > 1) glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
    else glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
    return rb;
}

void check_complete(const char* what) {
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string("incomplete framebuffer: ") + what);
}

}  // namespace

OsmesaTarget::OsmesaTarget(int width, int height, int samples, bool srgb)
    : width_(width), height_(height), samples_(samples), srgb_(srgb) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesaCreateContextAttribs failed (no OpenGL 3.3 core context)");
    dummy_.resize(4 * 4 * 4);
    if (!OSMesaMakeCurrent(ctx_, dummy_.data(), GL_UNSIGNED_BYTE, 4, 4))
        throw std::runtime_error("OSMesaMakeCurrent failed");
    if (renderer().find("llvmpipe") == std::string::npos)
        throw std::runtime_error("GL_RENDERER is '" + renderer() + "', not llvmpipe: refusing to use it as the reference");

    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const GLenum color_format = srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    color_ = make_renderbuffer(color_format, samples, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    // 32-bit float depth and 8-bit stencil, as softraster's buffers.
    depth_ = make_renderbuffer(GL_DEPTH32F_STENCIL8, samples, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    check_complete("drawing target");
    // A driver may give more samples than asked for (GL allows it): llvmpipe gives 4 for 2
    // (and for 8 and 16 where it has no such pattern), which would compare softraster's 2x
    // picture with a 4x one. Such a scene cannot be checked against this reference.
    if (samples > 1) {
        GLint got = 0;
        glBindRenderbuffer(GL_RENDERBUFFER, color_);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &got);
        if (got != samples)
            throw std::runtime_error("llvmpipe gives " + std::to_string(got) + " samples per pixel where the scene asks for " +
                                     std::to_string(samples) + ": it cannot be this scene's reference");
        glGenFramebuffers(1, &resolve_fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
        resolve_color_ = make_renderbuffer(color_format, 1, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color_);
        check_complete("resolve target");
    }
    bind_for_drawing();
}

OsmesaTarget::~OsmesaTarget() {
    if (!ctx_) return;
    glDeleteFramebuffers(1, &fbo_);
    glDeleteFramebuffers(1, &resolve_fbo_);
    const GLuint rbs[] = {color_, depth_, resolve_color_};
    glDeleteRenderbuffers(3, rbs);
    OSMesaDestroyContext(ctx_);
}

std::string OsmesaTarget::renderer() const {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? r : "";
}

void OsmesaTarget::bind_for_drawing() {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    // Encoding on write, blending in linear light, clears encoded and the resolve averaging
    // in linear light (GL 4.6, 17.3.7 and 18.3.1).
    if (srgb_) glEnable(GL_FRAMEBUFFER_SRGB);
    else glDisable(GL_FRAMEBUFFER_SRGB);
    glViewport(0, 0, width_, height_);
}

void OsmesaTarget::resolve() {
    if (samples_ <= 1) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

softraster::Image OsmesaTarget::read_pixels() {
    softraster::Image img(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 1 ? resolve_fbo_ : fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("glReadPixels failed");
    return img;
}

}  // namespace glref
