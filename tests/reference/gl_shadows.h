// The reference's shadow maps (docs/scene-format.md "Shadows"): per shadowed light a
// GL_DEPTH_COMPONENT32F array texture, one layer per face (a point light's cube has six),
// each filled by a depth pass with glPolygonOffset(slope_bias, 0), both faces, from the
// face's matrix S (softraster::shadow_matrix, shared with the scene loader as the camera's
// matrices are). The fragment shader reads the texels with texelFetch
// and compares them itself (gl_shaders.cpp, shadow_visibility), as the spec's PCF does.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "osmesa_target.h"
#include "softraster/scene/scene.h"

namespace glref {

class GlShadows {
public:
    static constexpr int kFirstUnit = 5;  // texture units kFirstUnit.. hold the maps

    explicit GlShadows(const softraster::Scene& scene);
    ~GlShadows();
    GlShadows(const GlShadows&) = delete;
    GlShadows& operator=(const GlShadows&) = delete;

    int count() const { return int(maps_.size()); }
    // The GLSL #define SHADOWS for the scene's programs.
    std::string defines() const;

    // A triangle draw that casts: its vertex array (positions at attribute 0) and model matrix.
    struct Caster {
        GLuint vao;
        GLsizei index_count;
        glm::mat4 model;
    };
    // The depth passes; the draw framebuffer and viewport are restored after.
    void draw(const std::vector<Caster>& casters) const;
    // The maps on their texture units and the uniforms of `program` that read them.
    void bind(GLuint program) const;

private:
    struct Face {
        glm::mat4 matrix{1.0f};
        glm::vec3 offset{0.0f};
        GLuint fbo = 0;  // its layer of the texture
    };
    struct Map {
        softraster::ShadowSettings settings;
        std::vector<Face> faces;  // one, or a cube's six (+x, -x, +y, -y, +z, -z)
        glm::vec3 light{0.0f};    // a cube's center
        GLuint texture = 0;
    };
    std::vector<Map> maps_;                  // directional lights first, then point and spot lights
    std::vector<int> directional_, punctual_;  // each light's map, or count() for none
    GLuint program_ = 0;                     // the depth pass's
};

}  // namespace glref
