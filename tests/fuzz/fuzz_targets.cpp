#include "fuzz_targets.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string_view>

#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/mesh.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::fuzz {
namespace {

namespace fs = std::filesystem;

// The loaders read files by path (the model's folder matters for its textures), so each
// input is written to a file of the target's extension in a folder of this process's own.
fs::path as_file(const uint8_t* data, size_t size, const std::string& ext) {
    static const fs::path dir = fs::temp_directory_path() / ("softraster_fuzz_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / ("input" + ext);
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return file;
}

// A model is also drawn, small: the loader's output must be something the pipeline takes.
void model(const uint8_t* data, size_t size, const std::string& ext) {
    const Model m = load_model(as_file(data, size, ext), MissingTexture::Warn);
    ModelPicture picture;
    picture.width = picture.height = 32;
    picture.samples = 1;
    SceneRenderer(model_scene(m, picture)).render();
}

const std::map<std::string, std::function<void(const uint8_t*, size_t)>>& targets() {
    static const std::map<std::string, std::function<void(const uint8_t*, size_t)>> all = {
        {"scene", [](const uint8_t* d, size_t n) { SceneRenderer(load_scene(as_file(d, n, ".json"))).render(); }},
        {"mesh_obj", [](const uint8_t* d, size_t n) { load_obj(as_file(d, n, ".obj")); }},
        {"mesh_ply", [](const uint8_t* d, size_t n) { load_ply(as_file(d, n, ".ply")); }},
        {"image_png", [](const uint8_t* d, size_t n) { read_image(std::string_view(reinterpret_cast<const char*>(d), n), "in", "png"); }},
        {"image_jpg", [](const uint8_t* d, size_t n) { read_image(std::string_view(reinterpret_cast<const char*>(d), n), "in", "jpg"); }},
        {"image_tga", [](const uint8_t* d, size_t n) { read_image(std::string_view(reinterpret_cast<const char*>(d), n), "in", "tga"); }},
        {"image_bmp", [](const uint8_t* d, size_t n) { read_image(std::string_view(reinterpret_cast<const char*>(d), n), "in", "bmp"); }},
        {"model_gltf", [](const uint8_t* d, size_t n) { model(d, n, ".gltf"); }},
        {"model_glb", [](const uint8_t* d, size_t n) { model(d, n, ".glb"); }},
        {"model_obj", [](const uint8_t* d, size_t n) { model(d, n, ".obj"); }},
        {"model_fbx", [](const uint8_t* d, size_t n) { model(d, n, ".fbx"); }},
        {"model_stl", [](const uint8_t* d, size_t n) { model(d, n, ".stl"); }},
        {"model_ply", [](const uint8_t* d, size_t n) { model(d, n, ".ply"); }},
        {"model_dae", [](const uint8_t* d, size_t n) { model(d, n, ".dae"); }},
        {"model_3ds", [](const uint8_t* d, size_t n) { model(d, n, ".3ds"); }},
    };
    return all;
}

}  // namespace

std::vector<std::string> target_names() {
    std::vector<std::string> names;
    for (const auto& [name, run] : targets()) names.push_back(name);
    return names;
}

void run_target(const std::string& target, const uint8_t* data, size_t size) {
    const auto it = targets().find(target);
    if (it == targets().end()) throw std::invalid_argument("unknown fuzz target '" + target + "'");
    try {
        it->second(data, size);
    } catch (const InputError&) {
        // a clean rejection: what bad input should get
    }
}

}  // namespace softraster::fuzz
