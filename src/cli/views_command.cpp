// softraster views: one model from many cameras, for data sets (multi-view training data,
// previews): color pictures, and on request depth, normals and foreground masks, with cameras.json
// holding each view's intrinsics and pose so that depth can be re-projected to points.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "cli/progress.h"
#include "softraster/error.h"
#include "softraster/io/atomic_write.h"
#include "softraster/io/image_io.h"
#include "softraster/io/image_write.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene_renderer.h"
#include "softraster/scene/surface_ids.h"

namespace softraster::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json rows(const auto& matrix) {
    json out = json::array();
    for (const auto& row : matrix) out.push_back(row);
    return out;
}

// The two file formats of depth and normals (--format).
void write_depth(const GrayImage<float>& distance, const fs::path& stem, bool png16, double scale, json& view) {
    if (!png16) {
        write_gray(distance, fs::path(stem).concat("_depth.exr"));
        view["depth"] = fs::path(stem).concat("_depth.exr").filename().string();
        return;
    }
    GrayImage<uint16_t> steps{distance.width, distance.height, std::vector<uint16_t>(distance.values.size(), 0)};
    for (size_t p = 0; p < steps.values.size(); ++p)
        if (std::isfinite(distance.values[p])) steps.values[p] = uint16_t(std::clamp(std::lround(distance.values[p] / scale), 1l, 65535l));
    write_gray(steps, fs::path(stem).concat("_depth.png"));
    view["depth"] = fs::path(stem).concat("_depth.png").filename().string();
    view["depth_scale"] = scale;
}

void write_normals(const Scene& scene, const SurfaceIds& ids, NormalSpace space, const fs::path& stem, bool png16, json& view) {
    const std::vector<glm::vec3> normals = surface_normals(scene, ids, space);
    const fs::path path = fs::path(stem).concat(png16 ? "_normals.png" : "_normals.exr");
    if (png16) {  // 0.5 n + 0.5 in 16 bits; (0, 0, 0), no unit vector's code, where empty
        std::vector<uint16_t> rgb(3 * normals.size(), 0);
        for (size_t p = 0; p < normals.size(); ++p)
            if (ids.object[p] >= 0)
                for (size_t k = 0; k < 3; ++k) rgb[3 * p + k] = uint16_t(std::lround((0.5 * normals[p][int(k)] + 0.5) * 65535.0));
        write_rgb(scene.width, scene.height, rgb, path);
    } else {
        std::vector<float> rgb(3 * normals.size());
        for (size_t p = 0; p < normals.size(); ++p)
            for (size_t k = 0; k < 3; ++k) rgb[3 * p + k] = normals[p][int(k)];
        write_rgb(scene.width, scene.height, rgb, path);
    }
    view["normals"] = path.filename().string();
}

}  // namespace

int run_views(const ViewsOptions& opt) {
    ModelOptions options = opt.model;
    if (options.background.empty()) options.background = "0,0,0,0";  // (transparent: the mask is the alpha)
    ModelPicture picture = options.picture(512);
    const Model model = load_model(opt.input, MissingTexture::Warn, picture.color_space);
    for (const std::string& w : model.warnings) std::fprintf(stderr, "softraster: warning: %s\n", w.c_str());
    std::error_code ec;  // (after the model is read: a bad file leaves nothing behind)
    fs::create_directories(opt.out, ec);
    if (ec) throw InputError(opt.out + ": cannot create the folder (" + ec.message() + ")");
    const BoundingSphere sphere = bounding_sphere(model.objects).value_or(BoundingSphere{});

    json cameras = {{"model", opt.input}, {"width", picture.width}, {"height", picture.height}, {"layout", opt.layout},
                    {"normalization", {{"center", {sphere.center.x, sphere.center.y, sphere.center.z}}, {"radius", sphere.radius}}},
                    {"conventions", "K in pixels, pixel (u, v) covering [u, u + 1) x [v, v + 1), v down; world_to_camera: OpenCV "
                                    "(camera looks down +z, y down); world_to_camera_gl: OpenGL (down -z, y up); depth: "
                                    "view-axis distance in world units (EXR: float, inf where empty; PNG: 16-bit steps of "
                                    "depth_scale, 0 where empty); normals: unit, at the pixel centers, in normals_space "
                                    "(EXR: float R, G, B = x, y, z; PNG: 16-bit 0.5 n + 0.5), 0 where empty"},
                    {"normals_space", opt.normals_space},
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
                     {"world_to_camera", rows(world_to_camera_cv(scene.camera))},
                     {"world_to_camera_gl", rows(world_to_camera_gl(scene.camera))}};
        write_png(color, fs::path(opt.out) / (std::string(stem) + ".png"));
        const fs::path stem_path = fs::path(opt.out) / stem;
        const bool png16 = opt.format == "png16";
        if (opt.depth) {
            GrayImage<float> depth = depth_picture(fb);
            for (float& z : depth.values) z = view_distance(z, scene.camera);
            write_depth(depth, stem_path, png16, double(scene.camera.far) / 65535.0, view);
        }
        if (opt.normals)
            write_normals(scene, surface_ids(scene, thread_count(opt.threads)),
                          opt.normals_space == "camera" ? NormalSpace::Camera : NormalSpace::World, stem_path, png16, view);
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
    write_file_atomically(json_path, cameras.dump(1) + "\n");  // last: its presence says the views are all there
    std::fprintf(stderr, "wrote %zu views and %s\n", dirs.size(), json_path.string().c_str());
    return 0;
}

}  // namespace softraster::cli
