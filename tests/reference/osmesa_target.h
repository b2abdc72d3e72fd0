// An off-screen OpenGL 3.3 core context on Mesa's llvmpipe (OSMesa), rendering into a
// framebuffer object with an RGBA8 (or SRGB8_ALPHA8, with GL_FRAMEBUFFER_SRGB on) color and a
// 32-bit float depth attachment, 1 or 4 samples.
// Test-only: the independent reference that softraster's pictures are checked against.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

#include "softraster/image.h"

namespace glref {

class OsmesaTarget {
public:
    // Throws std::runtime_error when no context can be made, or when GL_RENDERER is not
    // llvmpipe (the reference must be the renderer we claim to match).
    OsmesaTarget(int width, int height, int samples, bool srgb = false);
    ~OsmesaTarget();
    OsmesaTarget(const OsmesaTarget&) = delete;
    OsmesaTarget& operator=(const OsmesaTarget&) = delete;

    void bind_for_drawing();          // the (multisampled) framebuffer
    void resolve();                   // MSAA resolve into the single-sampled framebuffer
    softraster::Image read_pixels();  // row 0 = GL window row 0 = the top of our picture
    std::string renderer() const;

private:
    int width_, height_, samples_;
    bool srgb_;
    OSMesaContext ctx_ = nullptr;
    std::string dummy_;  // OSMesa needs a default buffer to make the context current
    GLuint fbo_ = 0, color_ = 0, depth_ = 0;        // drawing target
    GLuint resolve_fbo_ = 0, resolve_color_ = 0;    // single-sampled copy, for MSAA
};

}  // namespace glref
