#include <chrono>
#include <string>

#include "cli/commands.h"
#include "cli/output.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {

int run_showcase(const ShowcaseOptions& opt) {
    check_output_path(opt.out);
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = showcase_scene();
    const Image image = SceneRenderer(scene, thread_count(0)).render();
    write_output(image, opt.out, std::chrono::steady_clock::now() - start);
    return 0;
}

}  // namespace softraster::cli
