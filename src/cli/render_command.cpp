#include <chrono>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/output.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {

Run add_render_command(CLI::App& app) {
    struct Options {
        std::string scene, out;
        int threads = 0;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file (format version 1) to a PNG");
    cmd->add_option("scene", opt->scene, "Scene file (.json)")->required();
    cmd->add_option("-o,--output", opt->out, "Output PNG (default: the scene's name with .png, in this folder)");
    cmd->add_option("--threads", opt->threads, "Worker threads (0: one per core); the picture is the same for any count")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    cmd->footer("Example: softraster render scenes/tri_basic.json -o tri.png\nThe scene format: docs/scene-format.md in the softraster sources.");
    return [opt] {
        const std::filesystem::path scene_path = opt->scene;
        const std::filesystem::path out =
            opt->out.empty() ? std::filesystem::path(scene_path.stem().string() + ".png") : std::filesystem::path(opt->out);
        check_output_path(out);
        const auto start = std::chrono::steady_clock::now();
        const Scene scene = load_scene(scene_path);
        const Image image = SceneRenderer(scene, thread_count(opt->threads)).render();
        write_output(image, out, std::chrono::steady_clock::now() - start);
        return 0;
    };
}

}  // namespace softraster::cli
