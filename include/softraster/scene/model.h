// Model files as people have them (glTF 2.0, OBJ with MTL, FBX, STL, COLLADA, 3DS, PLY and
// the other formats assimp reads), turned into the scene's own objects: what `render MODEL`,
// `thumbnails` and a scene's "model" key draw.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "softraster/scene/scene.h"

namespace softraster {

struct Model {
    // One object per mesh per node that places it, with the node's world transform. A mesh
    // placed by several nodes (instancing) is one Mesh shared by their objects, not copies.
    std::vector<SceneObject> objects;
    std::vector<Camera> cameras;         // the file's cameras, placed by their nodes
    Lights lights;                       // the file's lights (KHR_lights_punctual), placed by their nodes
    std::vector<std::string> warnings;   // e.g. a texture that could not be read (drawn untextured)
    std::vector<std::string> ignored;    // what the file has that the pipeline does not draw yet
};

// What to do with a texture that is missing or unreadable: fail (scene files), or draw the
// material untextured and add a warning (render MODEL, thumbnails).
enum class MissingTexture { Fail, Warn };

// Reads a model file through assimp. Throws InputError("<path>: <what>") for a file it cannot
// use (unreadable, malformed, no triangles, non-finite positions...). `color`: the color
// space of the scene that draws it, which its base color and emissive textures take (their
// files are sRGB-encoded; a linear scene uses the stored values as they are).
Model load_model(const std::filesystem::path& path, MissingTexture missing = MissingTexture::Fail,
                 ColorSpace color = ColorSpace::Linear);

// Whether the file's extension is one load_model reads (case-insensitive).
bool is_model_file(const std::filesystem::path& path);

// The smallest sphere around the objects' transformed vertices that this cheap rule finds:
// centered on their bounding box, radius to the farthest vertex. None when nothing is drawn.
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
std::optional<BoundingSphere> bounding_sphere(const std::vector<SceneObject>& objects);

// How `render MODEL` and `thumbnails` picture a model.
enum class ModelView { ThreeQuarter, Front, Back, Left, Right, Top, Bottom, Iso };
struct ModelPicture {
    int width = 512, height = 512;
    glm::vec4 background{0.2f, 0.2f, 0.25f, 1.0f};  // as it appears in the picture (stored values / 255)
    int samples = 4;
    ModelView view = ModelView::ThreeQuarter;
    std::optional<glm::vec3> to_eye;  // instead of `view`: the direction from the model's center to the camera
    std::optional<Shading> shading;  // none: each material's own (lit, or unlit where the file says)
    int camera = -1;                 // >= 0: the file's camera with this index instead of framing
    ColorSpace color_space = ColorSpace::Srgb;  // glTF's: color textures and the picture sRGB-encoded
    ToneMapping tone_mapping;
    bool shadows = false;  // shadow maps for the key light or the file's lights (model_scene)
    int anisotropy = 1;    // every texture's max_anisotropy (texture.h): 1 is off
    bool ambient_occlusion = false;  // screen-space, the radius a tenth of the model's (model_scene)
    std::shared_ptr<const EnvironmentLighting> environment;  // image-based lighting for pbr materials
};

// A scene that shows the model: a perspective camera (30 degrees) whose view the model's
// bounding sphere fills, from the chosen side (+y is up), and the file's lights with a dim
// ambient light, or where the file has none a default rig (a key light from the upper left
// of the camera, a fill light from the right, ambient). With `shadows` the key light, or
// the file's first directional and spot lights (at most 4; spots at most 80 degrees wide),
// get the format's default shadow map with the bias scaled to the model's size. Throws
// InputError when `picture.camera` names no camera of the file.
Scene model_scene(const Model& model, const ModelPicture& picture);

// `count` directions from a model's center to cameras (unit vectors, +y up), for
// ModelPicture::to_eye: "sphere" evenly over the sphere (a Fibonacci lattice, pole to pole),
// "ring" around the vertical axis 20 degrees above the horizon, "random" uniform on the
// sphere, the same for the same seed. Throws InputError for another layout.
std::vector<glm::vec3> view_directions(const std::string& layout, int count, unsigned seed);

}  // namespace softraster
