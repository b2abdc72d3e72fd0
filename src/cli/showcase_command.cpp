#include <chrono>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/output.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {

Run add_showcase_command(CLI::App& app) {
    auto out = std::make_shared<std::string>("showcase.png");
    CLI::App* cmd = app.add_subcommand("showcase", "Render the built-in showcase scene (needs no files)");
    cmd->add_option("-o,--output", *out, "Output PNG")->capture_default_str();
    return [out] {
        check_output_path(*out);
        const auto start = std::chrono::steady_clock::now();
        const Scene scene = showcase_scene();
        const Image image = SceneRenderer(scene, thread_count(0)).render();
        write_output(image, *out, std::chrono::steady_clock::now() - start);
        return 0;
    };
}

}  // namespace softraster::cli
