#include <chrono>
#include <cstdio>
#include <string>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "cli/output.h"
#include "platform/terminal_picture.h"
#include "softraster/error.h"
#include "softraster/io/image_write.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/scene/animation.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

template <class T>
void write_buffer(const GrayImage<T>& picture, const std::string& path) {
    try {
        write_gray(picture, path);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
    std::fprintf(stderr, "wrote %s (%dx%d)\n", path.c_str(), picture.width, picture.height);
}

}  // namespace

int run_render(const RenderOptions& opt) {
    const std::filesystem::path scene_path = opt.scene;
    const std::filesystem::path out =
        opt.out.empty() ? std::filesystem::path(scene_path.stem().string() + ".png") : std::filesystem::path(opt.out);
    const bool write_file = !opt.terminal || !opt.out.empty();
    if (write_file) check_output_path(out);
    if (!opt.depth_out.empty()) check_output_path(opt.depth_out, {PictureFormat::Png, PictureFormat::Exr});
    if (!opt.stencil_out.empty()) check_output_path(opt.stencil_out, {PictureFormat::Png});
    const auto start = std::chrono::steady_clock::now();
    Scene scene = input_scene(scene_path, opt.model);
    scene = frame_at(scene, opt.time, opt.turntable > 0.0 ? std::optional<Turntable>(Turntable{opt.turntable}) : std::nullopt);
    const SceneRenderer renderer(scene, thread_count(opt.threads));
    Framebuffer fb = renderer.make_framebuffer();
    renderer.render(fb);
    const Image picture = renderer.resolve(fb);
    if (opt.terminal) platform::print_terminal_picture(picture, platform::terminal_size(), stdout);
    if (write_file) write_output(picture, out, std::chrono::steady_clock::now() - start, scene.color_space);
    // (The buffers at the resolution they were rendered at: supersampled scenes' are larger.)
    if (!opt.depth_out.empty()) {
        const GrayImage<float> depth = depth_picture(fb);
        if (picture_format(opt.depth_out) == PictureFormat::Exr) write_buffer(depth, opt.depth_out);
        else write_buffer(normalize_depth16(depth), opt.depth_out);
    }
    if (!opt.stencil_out.empty()) write_buffer(stencil_picture(fb, scene.clear_stencil), opt.stencil_out);
    return 0;
}

}  // namespace softraster::cli
