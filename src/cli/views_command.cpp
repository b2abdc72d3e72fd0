// softraster views: one model from many cameras, for data sets (multi-view training data,
// previews): color pictures, and on request depth and foreground masks, with cameras.json
// holding each view's intrinsics and pose so that depth can be re-projected to points.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "cli/progress.h"
#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/io/image_write.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json rows(const auto& matrix) {
    json out = json::array();
    for (const auto& row : matrix) out.push_back(row);
    return out;
}

}  // namespace

int run_views(const ViewsOptions& opt) {
    std::error_code ec;
    fs::create_directories(opt.out, ec);
    if (ec) throw InputError(opt.out + ": cannot create the folder (" + ec.message() + ")");
    ModelOptions options = opt.model;
    if (options.background.empty()) options.background = "0,0,0,0";  // (transparent: the mask is the alpha)
    ModelPicture picture = options.picture(512);
    const Model model = load_model(opt.input, MissingTexture::Warn, picture.color_space);
    for (const std::string& w : model.warnings) std::fprintf(stderr, "softraster: warning: %s\n", w.c_str());
    const BoundingSphere sphere = bounding_sphere(model.objects).value_or(BoundingSphere{});

    json cameras = {{"model", opt.input}, {"width", picture.width}, {"height", picture.height}, {"layout", opt.layout},
                    {"normalization", {{"center", {sphere.center.x, sphere.center.y, sphere.center.z}}, {"radius", sphere.radius}}},
                    {"conventions", "K in pixels, pixel (u, v) covering [u, u + 1) x [v, v + 1), v down; world_to_camera: OpenCV "
                                    "(camera looks down +z, y down); world_to_camera_gl: OpenGL (down -z, y up); depth: "
                                    "view-axis distance in world units, float EXR, inf where empty"},
                    {"views", json::array()}};
    const std::vector<glm::vec3> dirs = view_directions(opt.layout, opt.count, unsigned(opt.seed));
    Progress progress{dirs.size(), "views"};
    for (size_t i = 0; i < dirs.size(); ++i) {
        picture.to_eye = dirs[i];
        const Scene scene = model_scene(model, picture);
        const SceneRenderer renderer(scene, thread_count(opt.threads));
        Framebuffer fb = renderer.make_framebuffer();
        renderer.render(fb);
        const Image color = renderer.resolve(fb);
        char stem[32];
        std::snprintf(stem, sizeof stem, "%03zu", i);
        json view = {{"color", std::string(stem) + ".png"}, {"to_eye", {dirs[i].x, dirs[i].y, dirs[i].z}},
                     {"eye", {scene.camera.eye.x, scene.camera.eye.y, scene.camera.eye.z}},
                     {"K", rows(camera_intrinsics(scene.camera, scene.width, scene.height))},
                     {"world_to_camera", rows(world_to_camera_cv(scene.camera))}};
        json gl = view["world_to_camera"];  // (OpenGL's: the y and z rows back)
        for (size_t c = 0; c < 4; ++c) gl[1][c] = -gl[1][c].get<double>(), gl[2][c] = -gl[2][c].get<double>();
        view["world_to_camera_gl"] = gl;
        write_png(color, fs::path(opt.out) / (std::string(stem) + ".png"));
        if (opt.depth) {
            GrayImage<float> depth = depth_picture(fb);
            for (float& z : depth.values) z = view_distance(z, scene.camera);
            write_gray(depth, fs::path(opt.out) / (std::string(stem) + "_depth.exr"));
            view["depth"] = std::string(stem) + "_depth.exr";
        }
        if (opt.mask) {  // 255 where the model covers at least half the pixel
            GrayImage<uint8_t> mask{color.width, color.height, std::vector<uint8_t>(color.pixels.size())};
            for (size_t p = 0; p < color.pixels.size(); ++p) mask.values[p] = color.pixels[p].a >= 128 ? 255 : 0;
            write_gray(mask, fs::path(opt.out) / (std::string(stem) + "_mask.png"));
            view["mask"] = std::string(stem) + "_mask.png";
        }
        cameras["views"].push_back(view);
        progress.update(i + 1, "");
    }
    progress.clear();
    const fs::path json_path = fs::path(opt.out) / "cameras.json";
    {
        std::ofstream file(fs::path(json_path).concat(".tmp"));
        file << cameras.dump(1) << "\n";
        if (!file.flush()) throw InputError(json_path.string() + ": cannot write");
    }
    fs::rename(fs::path(json_path).concat(".tmp"), json_path);
    std::fprintf(stderr, "wrote %zu views and %s\n", dirs.size(), json_path.string().c_str());
    return 0;
}

}  // namespace softraster::cli
