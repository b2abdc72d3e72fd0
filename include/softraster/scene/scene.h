// A scene as the scene format describes it (docs/scene-format.md, versions 1 and 2), already
// validated and with its meshes and textures loaded.
#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "softraster/image.h"
#include "softraster/render_state.h"
#include "softraster/scene/mesh.h"
#include "softraster/shading/ambient_occlusion.h"
#include "softraster/shading/environment_lighting.h"
#include "softraster/shading/surface_vertex.h"  // Shading
#include "softraster/shading/texture.h"
#include "softraster/shading/tone_mapping.h"

namespace softraster {


struct Material {
    Shading shading = Shading::Lambert;
    glm::vec4 color{1.0f};
    std::shared_ptr<const Texture> texture;  // none: the texture term is 1
    Sampler sampler;  // version 1: one filter (nearest or bilinear), repeat or clamp
    glm::vec3 specular{0.0f};
    float shininess = 32.0f;
    BlendMode blend = BlendMode::Opaque;
    // Version 2:
    BlendEquationState blend_equation;  // when blend is Custom
    uint8_t color_mask = 0xf;           // bits r, g, b, a
    std::optional<float> alpha_cutoff;  // discard fragments whose alpha is below it
    bool alpha_to_coverage = false;
    bool affine = false;                // interpolation "affine": varyings linear in window space
    // Version 2, shading "pbr" (glTF's metallic-roughness; docs/scene-format.md
    // "Physically based materials"). The textures use the material's sampler and uv.
    float metallic = 0.0f, roughness = 0.5f;
    glm::vec3 emissive{0.0f};
    float occlusion_strength = 1.0f;
    std::shared_ptr<const Texture> metallic_roughness_texture;  // roughness from G, metallic from B
    std::shared_ptr<const Texture> occlusion_texture;           // R
    std::shared_ptr<const Texture> emissive_texture;            // RGB
    std::shared_ptr<const Texture> normal_texture;              // tangent-space normals (normal_mapping.h)
    float normal_scale = 1.0f;                                  // multiplies the map's x and y
};

// An object's per-fragment state (version 2; version 1 objects have the defaults).
struct ObjectState {
    bool depth_test = true;
    DepthFunc depth_func = DepthFunc::Less;
    std::optional<bool> depth_write;  // default: opaque objects write depth, blended ones do not
    float offset_factor = 0.0f, offset_units = 0.0f;
    bool stencil_test = false;
    StencilFace stencil_front, stencil_back;
    std::optional<ScissorRect> scissor;
};

// A mesh's edges drawn over it (version 2).
struct Wireframe {
    glm::vec3 color{0.0f};
    float width = 1.0f;
};

// A light's shadow map (version 2, docs/scene-format.md "Shadows").
struct ShadowSettings {
    int size = 1024;          // texels per side
    float bias = 0.02f;       // scene units a receiving point moves toward the light
    float slope_bias = 2.0f;  // the depth pass's polygon offset factor
    int pcf = 1;              // kernel radius r: (2r+1)^2 texels
};

struct DirectionalLight {
    glm::vec3 direction{0, -1, 0};  // the way the light travels
    glm::vec3 color{1.0f};
    std::optional<ShadowSettings> shadow;
};

// A point or spot light (version 2; glTF's KHR_lights_punctual).
struct PunctualLight {
    bool spot = false;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0, 0, -1};  // spot: the way the light travels
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;             // 0: no range (the falloff never ends)
    float inner_angle = 0.0f;       // spot: degrees from the axis, inner < outer <= 90
    float outer_angle = 45.0f;
    std::optional<ShadowSettings> shadow;  // a spot light's map, or a point light's cube
};

struct Lights {
    static constexpr size_t kMaxDirectional = 8;
    static constexpr size_t kMaxPunctual = 256;
    static constexpr size_t kMaxShadowed = 4;  // lights with a shadow map (shadow_mapping.h)
    glm::vec3 ambient{0.0f};
    std::vector<DirectionalLight> directional;
    std::vector<PunctualLight> punctual;  // point and spot lights
};

struct Camera {
    bool orthographic = false;
    glm::vec3 eye{0, 0, 3}, target{0, 0, 0}, up{0, 1, 0};
    float fov_y = 45.0f;   // degrees, perspective
    float height = 2.0f;   // view volume height, orthographic
    float near = 0.1f, far = 100.0f;
};

// Keyframes (animation.h, docs/scene-format.md "Animation").
struct ObjectMotion;
struct CameraMotion;

struct SceneObject {
    std::shared_ptr<const Mesh> mesh;
    glm::mat4 model{1.0f};  // T * Rz * Ry * Rx * S
    std::shared_ptr<const ObjectMotion> motion;  // version 2 or a model file's animation: model over time
    Material material;
    CullMode cull = CullMode::Back;
    FrontFace front_face = FrontFace::CCW;
    ObjectState state;
    // Version 2: what is drawn (primitive_indices in mesh.h), and how wide.
    Topology primitive = Topology::Triangles;
    float line_width = 1.0f, point_size = 1.0f;
    std::optional<Wireframe> wireframe;
};

struct Scene {
    int width = 640, height = 480;
    glm::vec4 background{0, 0, 0, 1};
    int samples = 1;
    int supersample = 1;    // rendered at supersample x the size, then box-filtered
    uint8_t clear_stencil = 0;
    bool sorted = true;     // v1 draw order (opaque, then blended back to front); false: file order
    // Version 2 (docs/scene-format.md "Color spaces"): sRGB decodes the color textures and
    // encodes the picture, so that light is lit and blended linearly; and the tone mapping.
    ColorSpace color_space = ColorSpace::Linear;
    ToneMapping tone_mapping;
    // Version 2: image-based lighting of pbr surfaces (docs/scene-format.md "Environment lighting").
    std::shared_ptr<const EnvironmentLighting> environment;
    // Version 2: screen-space ambient occlusion darkens the picture (docs/scene-format.md
    // "Ambient occlusion").
    std::optional<AmbientOcclusionSettings> ambient_occlusion;
    Camera camera;
    std::shared_ptr<const CameraMotion> camera_motion;  // version 2: the camera's eye and target over time
    Lights lights;
    std::vector<SceneObject> objects;
};

// Model matrix M = T * Rz(rz) * Ry(ry) * Rx(rx) * S, angles in degrees, computed in double
// precision from the left (rotate_euler gives ((m * Rz) * Ry) * Rx, for keyframes too).
glm::dmat4 rotate_euler(const glm::dmat4& m, const glm::dvec3& rotate_deg);
glm::mat4 model_matrix(const glm::vec3& translate, const glm::vec3& rotate_deg, const glm::vec3& scale);
// The normal matrix transpose(inverse(mat3(M))), in double precision: normals follow a
// non-uniform scale the way the surface does.
glm::dmat3 normal_matrix(const glm::mat4& model);
// gluLookAt and gluPerspective / glOrtho for the scene's camera and image aspect.
glm::mat4 view_matrix(const Camera& c);
glm::mat4 projection_matrix(const Camera& c, int width, int height);
// A perspective camera's intrinsics for a width x height picture, row by row: fx = fy =
// (height / 2) / tan(fov_y / 2), the principal point at the picture's center (pixel (u, v)
// covers [u, u + 1) x [v, v + 1), v down). Zero for an orthographic camera.
std::array<std::array<double, 3>, 3> camera_intrinsics(const Camera& c, int width, int height);
// World to camera, row by row, in OpenCV's convention (the camera looks down +z, y down):
// OpenGL's view_matrix with its y and z rows negated.
std::array<std::array<double, 4>, 4> world_to_camera_cv(const Camera& c);
// The same in OpenGL's convention (looking down -z, y up): view_matrix, row by row. The two
// differ by diag(1, -1, -1, 1).
std::array<std::array<double, 4>, 4> world_to_camera_gl(const Camera& c);
// The distance along the camera's view axis (world units, positive) of a surface at window
// depth z in [0, 1] (depth_picture in resolve.h); infinity at z = 1, where nothing was drawn.
float view_distance(float z, const Camera& c);

// Shadow maps (docs/scene-format.md "Shadows"): the world-space box of every triangle
// object's finite vertices, and a light's view-projection S that frames it.
struct Bounds {
    glm::vec3 lo{1.0f}, hi{-1.0f};  // empty while lo.x > hi.x
    bool empty() const { return lo.x > hi.x; }
};
Bounds shadow_bounds(const Scene& scene);
glm::mat4 shadow_matrix(const DirectionalLight& light, const Bounds& b);
glm::mat4 shadow_matrix(const PunctualLight& spot, const Bounds& b);
// A point light's cube face (0..5: looking along +x, -x, +y, -y, +z, -z): the unit axis, and S.
glm::vec3 cube_face_axis(int face);
glm::mat4 shadow_matrix(const PunctualLight& point, const Bounds& b, int face);
// The lookup's offset b: `bias` toward the light, against `travel` (the way the light goes).
glm::vec3 shadow_offset(const ShadowSettings& s, const glm::vec3& travel);

// Reads and validates a scene file; meshes and textures are resolved relative to it.
// Throws InputError with one line naming the file and the JSON path or line.
Scene load_scene(const std::filesystem::path& path);
// The same for a scene's JSON text: its meshes and textures resolved relative to `dir`, its
// errors naming `file` (the Python module's scenes given as dicts or strings).
Scene parse_scene(const std::string& text, const std::filesystem::path& dir, const std::string& file);

// Gives each object with a normal map a mesh with tangents (generate_tangents in mesh.h)
// where its mesh has none; objects that share a mesh share the copy.
void add_tangents(std::vector<SceneObject>& objects);

// The built-in showcase scene (needs no files).
Scene showcase_scene();

}  // namespace softraster
