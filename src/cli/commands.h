// The subcommands of the softraster program. Each takes its options as a plain struct and
// returns the process exit code; the command line (command_line.cpp, the one source file
// that includes CLI11) declares the options, fills the structs and runs the command given.
#pragma once
#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "cli/model_options.h"

namespace softraster::cli {

struct RenderOptions {
    std::string scene, out, depth_out, stencil_out;
    int threads = 0;
    ModelOptions model;
    double turntable = 0.0, time = 0.0;
    bool terminal = false;
};
int run_render(const RenderOptions& opt);

struct ShowcaseOptions {
    std::string out = "showcase.png";
};
int run_showcase(const ShowcaseOptions& opt);

struct BenchOptions {
    std::string scene;
    int frames = 20, warmup = 3, threads = 0;
    bool json = false, orbit = false, scaling = false;
};
int run_bench(const BenchOptions& opt);

struct ThumbnailsOptions {
    std::vector<std::string> inputs;
    std::string out, report;
    int jobs = 0, timeout = 60, max_memory = 4096;
    bool skip_existing = false, quiet = false;
    ModelOptions model;
};
int run_thumbnails(const ThumbnailsOptions& opt);

struct AnimateOptions {
    std::string input, out;
    double turntable = 0.0, duration = 0.0;
    int fps = 25, threads = 0;
    ModelOptions model;
};
int run_animate(const AnimateOptions& opt);

struct ViewOptions {
    std::string input, screenshots = ".";
    int threads = 0, orbit_frames = 0;
    bool terminal = false;
    ModelOptions model;
};
int run_view(const ViewOptions& opt);

struct ThumbnailOptions {
    std::string input, output, background = "0,0,0,0";
    int size = 256, timeout = 30;
    double max_file_size = 100.0;  // megabytes, as f3d's thumbnailer's default
};
int run_thumbnail(const ThumbnailOptions& opt);

struct ViewsOptions {
    std::string input, out, layout = "sphere";
    int count = 24, seed = 0, threads = 0;
    bool depth = false, normals = false, mask = false;
    std::string normals_space = "world", format = "exr";  // depth and normals: exr or png16
    ModelOptions model;
};
int run_views(const ViewsOptions& opt);

// --threads: a count, or 0 for one thread per core.
inline unsigned thread_count(int requested) {
    return requested > 0 ? unsigned(requested) : std::max(1u, std::thread::hardware_concurrency());
}

// Exit codes: 0 success, 1 internal failure, 2 bad input (scene, mesh, image or flag).
inline constexpr int kExitBadInput = 2;
// thumbnail: the time limit passed (--timeout).
inline constexpr int kExitTimedOut = 3;

}  // namespace softraster::cli
