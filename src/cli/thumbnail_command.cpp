// softraster thumbnail: one model file's picture for a file manager. The command of the
// freedesktop thumbnailer (data/softraster.thumbnailer), which Nautilus, Thunar, pcmanfm
// and Caja run as `softraster thumbnail --size %s %i %o`, GNOME inside bubblewrap: /usr
// read-only, no network, no $HOME, no display, and the input alone under /tmp.
//
// So it needs none of those; it reads the format from the file's bytes where the name
// lies (model_format.h), draws what it can when the files beside it (.mtl, .bin, textures)
// are out of reach, writes a PNG whatever the output's extension, never leaves a partial
// file, and gives up past a size and a time limit.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

namespace fs = std::filesystem;

// What the time limit's signal handler needs, prepared before it can fire: it may only
// make async-signal-safe calls (write, unlink, _exit).
char g_timeout_message[1024];
char g_partial_output[4096];

extern "C" void give_up(int) {
    if (g_partial_output[0]) unlink(g_partial_output);
    const ssize_t written = write(STDERR_FILENO, g_timeout_message, std::strlen(g_timeout_message));
    (void)written;
    _exit(kExitTimedOut);
}

void arm_time_limit(const ThumbnailOptions& opt) {
    std::snprintf(g_timeout_message, sizeof g_timeout_message, "softraster: error: %s: gave up after %d s (--timeout)\n", opt.input.c_str(),
                  opt.timeout);
    // write_png writes OUTPUT.tmp, then renames it into place (image_io.h).
    std::snprintf(g_partial_output, sizeof g_partial_output, "%s.tmp", opt.output.c_str());
    struct sigaction action {};
    action.sa_handler = give_up;
    sigaction(SIGALRM, &action, nullptr);
    alarm(unsigned(opt.timeout));
}

}  // namespace

int run_thumbnail(const ThumbnailOptions& opt) {
    std::error_code ec;
    const fs::path input = opt.input;
    if (!fs::is_regular_file(input, ec)) throw InputError(opt.input + (fs::exists(input, ec) ? ": not a regular file" : ": file not found"));
    const double megabytes = double(fs::file_size(input, ec)) / (1024.0 * 1024.0);
    if (megabytes > opt.max_file_size) {
        char what[128];
        std::snprintf(what, sizeof what, ": %.1f MB, over the limit of %g MB (--max-file-size)", megabytes, opt.max_file_size);
        throw InputError(opt.input + what);
    }
    const fs::path output_folder = fs::absolute(opt.output).parent_path();
    if (!fs::is_directory(output_folder, ec)) throw InputError(opt.output + ": its folder does not exist");
    arm_time_limit(opt);

    ModelOptions options;
    options.size = std::to_string(opt.size);
    options.background = opt.background;
    const ModelPicture picture = options.picture(opt.size);
    const Model model = load_model(input, MissingTexture::Warn, picture.color_space);
    const Scene scene = model_scene(model, picture);  // (the renderer keeps a reference to it)
    const SceneRenderer renderer(scene, thread_count(0));
    try {
        write_png(renderer.render(), opt.output);  // (a PNG whatever the name says, as the thumbnail spec wants)
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
    alarm(0);
    return 0;
}

}  // namespace softraster::cli
