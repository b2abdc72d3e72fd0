// The subcommands of the softraster program. Each registers its options on the CLI11 app
// and returns the function that runs it (which returns the process exit code).
#pragma once
#include <algorithm>
#include <functional>
#include <thread>

#include <CLI/CLI.hpp>

namespace softraster::cli {

using Run = std::function<int()>;

Run add_render_command(CLI::App& app);
Run add_showcase_command(CLI::App& app);
Run add_bench_command(CLI::App& app);
Run add_thumbnails_command(CLI::App& app);
Run add_animate_command(CLI::App& app);
Run add_view_command(CLI::App& app);

// --threads: a count, or 0 for one thread per core.
inline void add_threads_option(CLI::App& cmd, int& threads) {
    cmd.add_option("--threads", threads, "Worker threads (0: one per core); the pictures are the same for any count")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
}
inline unsigned thread_count(int requested) {
    return requested > 0 ? unsigned(requested) : std::max(1u, std::thread::hardware_concurrency());
}

// Exit codes: 0 success, 1 internal failure, 2 bad input (scene, mesh, image or flag).
inline constexpr int kExitBadInput = 2;

}  // namespace softraster::cli
