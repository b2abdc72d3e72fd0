// The reference's screen-space ambient occlusion (docs/scene-format.md "Ambient occlusion"):
// a depth pass of the opaque objects from the camera into a GL_DEPTH_COMPONENT32F texture
// (each object culled as in the picture), then the spec's formula in GLSL over a full-screen
// triangle into a GL_R32F texture, read back. Only the final multiplication of the picture
// by the factors is softraster's (apply_ambient_occlusion).
#pragma once
#include <vector>

#include <glm/mat4x4.hpp>

#include "osmesa_target.h"
#include "softraster/scene/scene.h"

namespace glref {

class GlAmbientOcclusion {
public:
    // width x height: the picture as drawn (supersampled).
    GlAmbientOcclusion(const softraster::Scene& scene, int width, int height);
    ~GlAmbientOcclusion();
    GlAmbientOcclusion(const GlAmbientOcclusion&) = delete;
    GlAmbientOcclusion& operator=(const GlAmbientOcclusion&) = delete;

    bool active() const { return program_ != 0; }

    // An opaque triangle draw: its vertex array (positions at attribute 0), model matrix and faces.
    struct Occluder {
        GLuint vao;
        GLsizei index_count;
        glm::mat4 model;
        softraster::CullMode cull;
        softraster::FrontFace front_face;
    };
    // The depth pass; the draw framebuffer and viewport are restored after.
    void draw_depth(const std::vector<Occluder>& occluders) const;
    // The factors, row 0 at the top of the picture.
    std::vector<float> factors() const;

private:
    int width_, height_;
    softraster::AmbientOcclusionSettings settings_;
    glm::mat4 view_, projection_;
    GLuint depth_texture_ = 0, depth_fbo_ = 0, ao_texture_ = 0, ao_fbo_ = 0, vao_ = 0;
    GLuint depth_program_ = 0, program_ = 0;
};

}  // namespace glref
