#include <chrono>
#include <cstdio>
#include <memory>
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

Run add_render_command(CLI::App& app) {
    struct Options {
        std::string scene, out, depth_out, stencil_out;
        int threads = 0;
        ModelOptions model;
        double turntable = 0.0, time = 0.0;
        bool terminal = false;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file or a model file to a picture (PNG, TGA, PPM or EXR)");
    cmd->add_option("input", opt->scene,
                    "Scene file (.json), or a model file (glTF, GLB, OBJ, FBX, STL, DAE, 3DS, PLY...) to frame and light automatically")
        ->required();
    cmd->add_option("-o,--output", opt->out,
                    "Output picture, format by extension: .png, .tga, .ppm, .exr (float, linear) (default: the scene's name with .png)");
    cmd->add_option("--depth-out", opt->depth_out,
                    "Also write the depth buffer: .png (16-bit, scaled from its least to its greatest finite value) or .exr (float, as stored)");
    cmd->add_option("--stencil-out", opt->stencil_out, "Also write the stencil buffer as an 8-bit gray .png");
    add_threads_option(*cmd, opt->threads);
    cmd->add_flag("--terminal", opt->terminal,
                  "Also draw the picture in the terminal (24-bit color half blocks, sized to the terminal); without -o, only there");
    add_model_options(*cmd, opt->model, 512);
    cmd->add_option("--time", opt->time,
                    "Seconds into the scene's keyframes or the model's animation, and the turntable (the same picture as that frame of 'animate')")
        ->check(CLI::Range(0.0, 1e9))
        ->capture_default_str();
    cmd->add_option("--turntable", opt->turntable, "The frame of 'animate --turntable SECONDS' at --time")->check(CLI::Range(1e-3, 1e6));
    cmd->footer("Examples:\n  softraster render scenes/tri_basic.json -o tri.png\n"
                "  softraster render duck.glb -o duck.png --size 800x600 --view front\n"
                "The model options (--size ... --camera) apply to model files only.\n"
                "The scene format: docs/scene-format.md in the softraster sources.");
    return [opt, cmd] {
        const std::filesystem::path scene_path = opt->scene;
        const std::filesystem::path out =
            opt->out.empty() ? std::filesystem::path(scene_path.stem().string() + ".png") : std::filesystem::path(opt->out);
        const bool write_file = !opt->terminal || !opt->out.empty();
        if (write_file) check_output_path(out);
        if (!opt->depth_out.empty()) check_output_path(opt->depth_out, {PictureFormat::Png, PictureFormat::Exr});
        if (!opt->stencil_out.empty()) check_output_path(opt->stencil_out, {PictureFormat::Png});
        const auto start = std::chrono::steady_clock::now();
        Scene scene = input_scene(scene_path, opt->model, *cmd);
        scene = frame_at(scene, opt->time, opt->turntable > 0.0 ? std::optional<Turntable>(Turntable{opt->turntable}) : std::nullopt);
        const SceneRenderer renderer(scene, thread_count(opt->threads));
        Framebuffer fb = renderer.make_framebuffer();
        renderer.render(fb);
        const Image picture = renderer.resolve(fb);
        if (opt->terminal) platform::print_terminal_picture(picture, platform::terminal_size(), stdout);
        if (write_file) write_output(picture, out, std::chrono::steady_clock::now() - start, scene.color_space);
        // (The buffers at the resolution they were rendered at: supersampled scenes' are larger.)
        if (!opt->depth_out.empty()) {
            const GrayImage<float> depth = depth_picture(fb);
            if (picture_format(opt->depth_out) == PictureFormat::Exr) write_buffer(depth, opt->depth_out);
            else write_buffer(normalize_depth16(depth), opt->depth_out);
        }
        if (!opt->stencil_out.empty()) write_buffer(stencil_picture(fb, scene.clear_stencil), opt->stencil_out);
        return 0;
    };
}

}  // namespace softraster::cli
