// The subcommands of the softraster program. Each registers its options on the CLI11 app
// and returns the function that runs it (which returns the process exit code).
#pragma once
#include <functional>

#include <CLI/CLI.hpp>

namespace softraster::cli {

using Run = std::function<int()>;

Run add_render_command(CLI::App& app);
Run add_showcase_command(CLI::App& app);
Run add_bench_command(CLI::App& app);

// Exit codes: 0 success, 1 internal failure, 2 bad input (scene, mesh, image or flag).
inline constexpr int kExitBadInput = 2;

}  // namespace softraster::cli
