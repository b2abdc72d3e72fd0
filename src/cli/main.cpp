// softraster: render 3D scenes on the CPU.
#include <malloc.h>

#include <cstdio>
#include <exception>
#include <iostream>

#include "cli/commands.h"
#include "git_commit.h"  // (generated: SOFTRASTER_GIT_COMMIT)
#include "softraster/error.h"

int main(int argc, char** argv) {
    using namespace softraster;
    // Commands that draw many frames (animate, view, thumbnails, bench --orbit) set each one
    // up anew, and a frame's buffers are large: glibc would hand them back to the kernel
    // (mmap/munmap) and take them again, zeroed page by page. Keeping them in the heap lets the
    // next frame reuse the memory (docs/performance.md, "Frames in a row").
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    CLI::App app{"softraster: a CPU rasterizer that renders scene files (format versions 1 and 2) and model files (glTF, OBJ, FBX, STL...) to pictures"};
    app.set_version_flag("--version", "softraster " SOFTRASTER_VERSION " (commit " SOFTRASTER_GIT_COMMIT ")");
    app.require_subcommand(1);
    app.footer("Run 'softraster COMMAND --help' for a command's options.\n"
               "Exit codes: 0 success, 1 internal error, 2 bad input (scene, mesh, image or flag).");
    const cli::Run render = cli::add_render_command(app);
    const cli::Run showcase = cli::add_showcase_command(app);
    const cli::Run bench = cli::add_bench_command(app);
    const cli::Run thumbnails = cli::add_thumbnails_command(app);
    const cli::Run animate = cli::add_animate_command(app);
    const cli::Run view = cli::add_view_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "softraster: error: " << e.what() << " (see softraster --help)\n";
        return cli::kExitBadInput;
    }
    try {
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("showcase")) return showcase();
        if (app.got_subcommand("bench")) return bench();
        if (app.got_subcommand("thumbnails")) return thumbnails();
        if (app.got_subcommand("animate")) return animate();
        if (app.got_subcommand("view")) return view();
    } catch (const InputError& e) {
        std::cerr << "softraster: error: " << e.what() << "\n";
        return cli::kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "softraster: internal error: " << e.what() << "\n";
        return 1;
    }
    return 1;
}
