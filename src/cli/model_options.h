// The options of the commands that picture model files (render MODEL, thumbnails): size,
// view, background, samples, shading, the file's camera. (Declared on the command line in
// command_line.cpp.)
#pragma once
#include <filesystem>
#include <memory>
#include <string>

#include "softraster/scene/model.h"

namespace softraster::cli {

struct ModelOptions {
    std::string size, view = "three-quarter", background, shading, color_space = "srgb", tone_mapping = "none";
    int samples = 4, camera = -1;
    float exposure = 1.0f;
    bool shadows = false;
    int anisotropy = 1;
    bool ambient_occlusion = false;
    std::string env;
    float env_intensity = 1.0f;
    bool env_background = false;
    bool verbose = false;

    // The picture these options describe; `default_size` when --size is not given.
    // Throws InputError for a value that cannot be used.
    ModelPicture picture(int default_size) const;
    // Whether any option that only models take was given (an error for `render SCENE.json`;
    // set by the command line).
    bool given = false;
};

// The scene of a command's input: a scene file (.json), where the model options are an
// error, or a model file pictured with them (textures that cannot be read are drawn
// without, with a warning line; -v says what the file has that is not drawn).
Scene input_scene(const std::filesystem::path& path, const ModelOptions& options);

}  // namespace softraster::cli
