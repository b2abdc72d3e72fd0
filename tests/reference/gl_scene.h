// A scene (format version 1) uploaded to OpenGL and drawn with GLSL shaders that follow the
// spec's formulas. Independent of softraster's pipeline: it shares only the scene loader
// (meshes, textures, the spec's matrices), which has its own unit tests.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include "gl_ambient_occlusion.h"
#include "gl_environment.h"
#include "gl_shadows.h"
#include "osmesa_target.h"
#include "softraster/scene/scene.h"

namespace glref {

class GlScene {
public:
    explicit GlScene(const softraster::Scene& scene);
    ~GlScene();
    GlScene(const GlScene&) = delete;
    GlScene& operator=(const GlScene&) = delete;

    // Clear and every draw, in the spec's order; the caller resolves and reads back.
    void draw_frame() const;
    // Ambient occlusion (if the scene has it) on the picture read back, before the
    // supersampling filter.
    void apply_ambient_occlusion(softraster::Image& picture) const;

    struct Draw;

private:
    const softraster::Scene& scene_;
    std::map<std::string, GLuint> programs_;  // by their #defines
    std::vector<std::unique_ptr<Draw>> draws_;
    std::unique_ptr<GlShadows> shadows_;
    std::unique_ptr<GlEnvironment> environment_;
    std::vector<GlShadows::Caster> casters_;  // the opaque triangle draws
    std::unique_ptr<GlAmbientOcclusion> occlusion_;
    std::vector<GlAmbientOcclusion::Occluder> occluders_;  // the same draws, with their faces
};

}  // namespace glref
