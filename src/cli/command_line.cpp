// The command line: every command's options (CLI11), parsed into the command's option
// struct (commands.h), then the command run. The one source file that includes CLI11, whose
// header compiles a few seconds' worth of code into every file that includes it.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command_line.h"
#include "cli/command_tree.h"
#include "cli/commands.h"
#include "git_commit.h"  // (generated: SOFTRASTER_GIT_COMMIT)
#include "softraster/error.h"

namespace softraster::cli {
namespace {

using Run = std::function<int()>;

// --threads: a count, or 0 for one thread per core.
// The scene or model file of a command that shows one (animate, view).
void add_input_option(CLI::App& cmd, std::string& input) {
    cmd.add_option("input", input, "Scene file (.json) or model file (glTF, GLB, OBJ, FBX, STL...)")->required();
}

void add_threads_option(CLI::App& cmd, int& threads) {
    cmd.add_option("--threads", threads, "Worker threads (0: one per core); the pictures are the same for any count")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
}

void add_model_options(CLI::App& cmd, ModelOptions& opt, int default_size) {
    cmd.add_option("--size", opt.size, "Picture size W or WxH (default " + std::to_string(default_size) + ")");
    cmd.add_option("--view", opt.view, "Side the model is seen from")
        ->check(CLI::IsMember({"three-quarter", "front", "back", "left", "right", "top", "bottom", "iso"}))
        ->capture_default_str();
    cmd.add_option("--background", opt.background, "Background R,G,B[,A] (0 to 1) or #RRGGBB[AA] (default 0.2,0.2,0.25)");
    cmd.add_option("--samples", opt.samples, "MSAA samples per pixel: 1, 2, 4, 8 or 16")
        ->check(CLI::IsMember({1, 2, 4, 8, 16}))
        ->capture_default_str();
    cmd.add_option("--shading", opt.shading, "Shading for every material (default: lambert, or unlit where the file says)")
        ->check(CLI::IsMember({"unlit", "flat", "gouraud", "lambert", "blinn_phong", "phong", "pbr", "normals", "depth"}));
    cmd.add_option("--camera", opt.camera, "Look through the file's camera N (0 is the first) instead of framing the model")
        ->check(CLI::Range(0, 1 << 20));
    cmd.add_option("--color-space", opt.color_space,
                   "srgb: color textures decoded, light added and blended linearly, the picture encoded (as glTF intends); "
                   "linear: every value used as stored")
        ->check(CLI::IsMember({"srgb", "linear"}))
        ->capture_default_str();
    cmd.add_option("--tone-mapping", opt.tone_mapping, "Tone curve for bright light: none, reinhard or aces")
        ->check(CLI::IsMember({"none", "reinhard", "aces"}))
        ->capture_default_str();
    cmd.add_option("--exposure", opt.exposure, "Light multiplied by this before the tone curve")
        ->check(CLI::Range(1e-6, 1e6))
        ->capture_default_str();
    cmd.add_flag("--shadows", opt.shadows,
                 "Shadow maps for the key light, or the file's lights (at most 4)");
    cmd.add_flag("--ssao", opt.ambient_occlusion, "Screen-space ambient occlusion: creases and contacts darken (radius a tenth of the model's)");
    cmd.add_option("--anisotropy", opt.anisotropy, "Anisotropic filtering: up to this many texture lookups along a stretched footprint (1 to 16)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    cmd.add_option("--env", opt.env, "An equirectangular .hdr or .exr picture that lights pbr materials (image-based lighting)");
    cmd.add_option("--env-intensity", opt.env_intensity, "The environment's light multiplied by this")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    cmd.add_flag("--env-background", opt.env_background, "Show the --env picture behind the model instead of --background");
    cmd.add_flag("-v,--verbose", opt.verbose, "Also say what the file has that is not drawn");
}

// Whether any option that only models take was given (an error for `render SCENE.json`).
bool model_options_given(const CLI::App& cmd) {
    for (const char* name : {"--size", "--view", "--background", "--samples", "--shading", "--camera", "--color-space", "--tone-mapping",
                             "--exposure", "--shadows", "--anisotropy", "--ssao", "--env", "--env-intensity", "--env-background"})
        if (cmd.count(name) > 0) return true;
    return false;
}

// The run of a command that takes the model options: it also learns whether any was given.
template <class Options>
Run model_command(std::shared_ptr<Options> opt, const CLI::App* cmd, int (*run)(const Options&)) {
    return [opt, cmd, run] {
        opt->model.given = model_options_given(*cmd);
        return run(*opt);
    };
}

Run add_render(CLI::App& app) {
    auto opt = std::make_shared<RenderOptions>();
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
    return model_command(opt, cmd, run_render);
}

Run add_showcase(CLI::App& app) {
    auto opt = std::make_shared<ShowcaseOptions>();
    CLI::App* cmd = app.add_subcommand("showcase", "Render the built-in showcase scene (needs no files)");
    cmd->add_option("-o,--output", opt->out, "Output PNG")->capture_default_str();
    return [opt] { return run_showcase(*opt); };
}

Run add_bench(CLI::App& app) {
    auto opt = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand("bench", "Time frames of a scene: clear, all draws and the MSAA resolve");
    cmd->add_option("scene", opt->scene, "Scene file (.json)")->required();
    cmd->add_option("--frames", opt->frames, "Timed frames")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--warmup", opt->warmup, "Untimed frames first")->check(CLI::Range(0, 100000))->capture_default_str();
    add_threads_option(*cmd, opt->threads);
    cmd->add_flag("--json", opt->json, "Print one JSON line instead of text");
    CLI::Option* orbit = cmd->add_flag("--orbit", opt->orbit,
                                       "Turn the objects once around in the timed frames (the turntable of 'animate'), each frame set up "
                                       "anew as 'view' and 'animate' do, and report frames per second");
    cmd->add_flag("--scaling", opt->scaling,
                  "Draw the frames on 1 thread and on --threads in turn, frame by frame, and report how much faster the second are "
                  "(a slow spell of a shared machine then falls on both)")
        ->excludes(orbit);
    return [opt] { return run_bench(*opt); };
}

Run add_thumbnails(CLI::App& app) {
    auto opt = std::make_shared<ThumbnailsOptions>();
    CLI::App* cmd = app.add_subcommand("thumbnails", "Draw a thumbnail of every model file in folders, globs and lists");
    cmd->add_option("inputs", opt->inputs, "Model files, folders (searched recursively by extension) and glob patterns")->required();
    cmd->add_option("--out", opt->out, "Output folder; pictures mirror the input tree as NAME.EXT.png")->required();
    cmd->add_option("--jobs", opt->jobs, "Models drawn at once (0: one per core)")->check(CLI::Range(0, 1024))->capture_default_str();
    cmd->add_option("--timeout", opt->timeout, "Seconds a model may take before it is given up")
        ->check(CLI::Range(1, 86400))
        ->capture_default_str();
    cmd->add_option("--max-memory", opt->max_memory, "Megabytes of address space each model may use before it is given up")
        ->check(CLI::Range(256, 1 << 22))
        ->capture_default_str();
    cmd->add_flag("--skip-existing", opt->skip_existing, "Leave inputs whose picture exists (resume an interrupted run)");
    cmd->add_option("--report", opt->report, "JSON report of every input and its result (default OUT/thumbnails.json)");
    cmd->add_flag("-q,--quiet", opt->quiet, "No line per file and no progress bar; failures and the summary still print");
    add_model_options(*cmd, opt->model, 256);
    cmd->footer("Example: softraster thumbnails models/ 'more/*.glb' --out thumbs/ --size 256\n"
                "Exit codes: 0 every file drawn (or skipped), 1 some failed (see the report), 2 bad usage.");
    return model_command(opt, cmd, run_thumbnails);
}

Run add_animate(CLI::App& app) {
    auto opt = std::make_shared<AnimateOptions>();
    CLI::App* cmd = app.add_subcommand("animate", "Render a scene's keyframes, a model's animation or a turntable to a video, a GIF or numbered pictures");
    add_input_option(*cmd, opt->input);
    cmd->add_option("-o,--output", opt->out, "Output by extension: .mp4 (H.264), .webm (VP9), .gif, or numbered pictures such as frames/%04d.png")
        ->required();
    cmd->add_option("--turntable", opt->turntable,
                    "Seconds per full turn of the objects about the vertical axis (default: 4 where nothing else moves)")
        ->check(CLI::Range(1e-3, 1e6));
    cmd->add_option("--duration", opt->duration, "Seconds of animation (default: to the last key, else one turn)")->check(CLI::Range(1e-3, 1e6));
    cmd->add_option("--fps", opt->fps, "Frames per second")->check(CLI::Range(1, 240))->capture_default_str();
    add_threads_option(*cmd, opt->threads);
    add_model_options(*cmd, opt->model, 512);
    cmd->footer("Examples:\n  softraster animate model.glb --turntable 4 -o spin.mp4\n"
                "  softraster animate model.glb --size 320 --fps 20 -o spin.gif\n"
                "  softraster animate scene.json --duration 2 -o frames/%04d.png\n"
                "Frame k shows time k / fps: the same picture as 'render --time k/fps' (with the same --turntable).");
    return model_command(opt, cmd, run_animate);
}

Run add_view(CLI::App& app) {
    auto opt = std::make_shared<ViewOptions>();
    CLI::App* cmd = app.add_subcommand("view", "Show a scene or model file in a window: turn it around, change the settings live");
    add_input_option(*cmd, opt->input);
    cmd->add_option("--screenshots", opt->screenshots, "Folder the screenshot key (p or F12) writes softraster-view-NNN.png into")
        ->capture_default_str();
    cmd->add_option("--orbit-frames", opt->orbit_frames,
                    "Turn the objects once around in N frames as fast as they draw, print the frame rate and quit (compare 'bench --orbit')")
        ->check(CLI::Range(1, 100000));
    cmd->add_flag("--terminal", opt->terminal, "Draw in this terminal (24-bit color half blocks) instead of a window: the keys work the same");
    add_threads_option(*cmd, opt->threads);
    add_model_options(*cmd, opt->model, 512);
    cmd->footer("Mouse: drag to turn, right-drag to pan, wheel to zoom. Keys: arrows turn and tilt by 15 degrees, r reset,\n"
                "s shading, w wireframe, m MSAA, c culling, d depth picture, f texture filter, space pause the keyframes,\n"
                "p or F12 screenshot, q or Esc quit.\n"
                "The file reloads when it changes; an error in it is shown and the last good version stays.");
    return model_command(opt, cmd, run_view);
}

Run add_thumbnail(CLI::App& app) {
    auto opt = std::make_shared<ThumbnailOptions>();
    CLI::App* cmd = app.add_subcommand("thumbnail", "Draw one model file's thumbnail for a file manager (the freedesktop thumbnailer's command)");
    cmd->add_option("input", opt->input, "Model file (its format read from its first bytes where the extension lies or is missing)")->required();
    cmd->add_option("output", opt->output, "Output picture: always a PNG, whatever its extension")->required();
    cmd->add_option("-s,--size", opt->size, "Width and height in pixels")->check(CLI::Range(8, 4096))->capture_default_str();
    cmd->add_option("--background", opt->background, "Background R,G,B,A (0 to 1) or #RRGGBBAA; transparent by default")->capture_default_str();
    cmd->add_option("--max-file-size", opt->max_file_size, "Megabytes: a larger file is not read")->check(CLI::Range(0.001, 1e6))->capture_default_str();
    cmd->add_option("--timeout", opt->timeout, "Seconds before giving up (exit code 3, no output left behind)")
        ->check(CLI::Range(1, 86400))
        ->capture_default_str();
    cmd->footer("Example (the line softraster.thumbnailer gives file managers): softraster thumbnail --size 256 model.glb thumb.png\n"
                "Exit codes: 0 drawn, 2 bad input (unreadable, too large, nothing to draw), 3 timed out.");
    return [opt] { return run_thumbnail(*opt); };
}

Run add_views(CLI::App& app) {
    auto opt = std::make_shared<ViewsOptions>();
    CLI::App* cmd = app.add_subcommand("views", "Render one model file from many cameras for data sets: pictures, depth, masks and cameras.json");
    cmd->add_option("input", opt->input, "Model file (glTF, GLB, OBJ, FBX, STL, DAE, 3DS, PLY...)")->required();
    cmd->add_option("--out", opt->out, "Output folder: NNN.png, NNN_depth.exr, NNN_normals.exr, NNN_mask.png and cameras.json")->required();
    cmd->add_option("--count", opt->count, "Views")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--layout", opt->layout, "Cameras evenly over a sphere, on a ring 20 degrees above the horizon, or at random")
        ->check(CLI::IsMember({"sphere", "ring", "random"}))
        ->capture_default_str();
    cmd->add_option("--seed", opt->seed, "Seed of --layout random (the same views for the same seed)")->capture_default_str();
    cmd->add_flag("--depth", opt->depth, "Also write each view's depth: the view-axis distance in world units, inf (EXR) or 0 (PNG) where empty");
    cmd->add_flag("--normals", opt->normals, "Also write each view's surface normals at the pixel centers, unit, 0 where empty");
    cmd->add_option("--normals-space", opt->normals_space, "world, or camera (OpenCV's axes: x right, y down, z forward)")
        ->check(CLI::IsMember({"world", "camera"}))
        ->capture_default_str();
    cmd->add_option("--format", opt->format,
                    "Depth and normals as float EXR, or 16-bit PNG (depth in steps of the view's depth_scale in cameras.json, "
                    "normals as 0.5 n + 0.5)")
        ->check(CLI::IsMember({"exr", "png16"}))
        ->capture_default_str();
    cmd->add_flag("--mask", opt->mask, "Also write each view's foreground mask: 8-bit PNG, 255 where the model covers the pixel");
    add_threads_option(*cmd, opt->threads);
    add_model_options(*cmd, opt->model, 512);
    cmd->footer("Example: softraster views model.glb --count 24 --size 512 --out views/ --depth --normals --mask\n"
                "The background is transparent unless --background says otherwise; --view does not apply.\n"
                "cameras.json: each view's K (pixels) and world-to-camera matrix (OpenCV's and OpenGL's conventions), "
                "and the model's center and radius (its normalization).");
    return model_command(opt, cmd, run_views);
}

// The command tree as plain data (command_tree.h).
std::vector<std::string> choices_of(const CLI::Option& o) {  // IsMember's description: {a,b,c}
    std::vector<std::string> choices;
    const std::string type = o.get_type_name();
    const size_t open = type.find('{'), close = type.find('}', open);
    if (open == std::string::npos || close == std::string::npos) return choices;
    const std::string list = type.substr(open + 1, close - open - 1);
    for (size_t at = 0; at <= list.size();) {
        const size_t comma = std::min(list.find(',', at), list.size());
        choices.push_back(list.substr(at, comma - at));
        at = comma + 1;
    }
    return choices;
}
std::vector<OptionInfo> option_infos(const CLI::App& app) {
    std::vector<OptionInfo> infos;
    for (const CLI::Option* o : app.get_options([](const CLI::Option* o) { return o->nonpositional(); })) {
        OptionInfo info;
        for (const std::string& s : o->get_snames()) info.names.push_back("-" + s);
        for (const std::string& l : o->get_lnames()) info.names.push_back("--" + l);
        info.takes_value = o->get_type_size() > 0;
        const std::string type = o->get_type_name();
        info.numeric = type.rfind("INT", 0) == 0 || type.rfind("FLOAT", 0) == 0 || type.rfind("UINT", 0) == 0;
        info.choices = choices_of(*o);
        infos.push_back(info);
    }
    return infos;
}
std::vector<CommandInfo> command_infos(const CLI::App& app) {
    std::vector<CommandInfo> infos;
    for (const CLI::App* cmd : app.get_subcommands([](const CLI::App*) { return true; })) {
        CommandInfo info{cmd->get_name(), option_infos(*cmd), false, {}};
        for (const CLI::Option* o : cmd->get_options([](const CLI::Option* o) { return o->get_positional(); })) {
            info.takes_files = true;
            const std::vector<std::string> choices = choices_of(*o);
            info.positional_choices.insert(info.positional_choices.end(), choices.begin(), choices.end());
        }
        infos.push_back(info);
    }
    return infos;
}

Run add_completion(CLI::App& app) {
    auto shell = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("completion", "Print the shell completion script for softraster's commands and options");
    cmd->add_option("shell", *shell, "The shell")->check(CLI::IsMember({"bash"}))->required();
    cmd->footer("Example: source <(softraster completion bash)\n"
                "The package installs it to share/bash-completion/completions, where bash finds it by itself.");
    return [shell, &app] {
        std::fputs(bash_completion(command_infos(app), option_infos(app)).c_str(), stdout);
        return 0;
    };
}

}  // namespace

int run_command_line(int argc, char** argv) {
    CLI::App app{"softraster: a CPU rasterizer that renders scene files (format versions 1 and 2) and model files (glTF, OBJ, FBX, STL...) to pictures"};
    app.name("softraster");  // (not argv[0]: the help and the man pages made from it name the program so)
    app.set_version_flag("--version", "softraster " SOFTRASTER_VERSION " (commit " SOFTRASTER_GIT_COMMIT ")");
    app.require_subcommand(1);
    app.footer("Run 'softraster COMMAND --help' for a command's options.\n"
               "Exit codes: 0 success, 1 internal error, 2 bad input (scene, mesh, image or flag).");
    const Run render = add_render(app);
    const Run showcase = add_showcase(app);
    const Run bench = add_bench(app);
    const Run thumbnails = add_thumbnails(app);
    const Run animate = add_animate(app);
    const Run view = add_view(app);
    const Run thumbnail = add_thumbnail(app);
    const Run views = add_views(app);
    const Run completion = add_completion(app);
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
        return kExitBadInput;
    }
    try {
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("showcase")) return showcase();
        if (app.got_subcommand("bench")) return bench();
        if (app.got_subcommand("thumbnails")) return thumbnails();
        if (app.got_subcommand("animate")) return animate();
        if (app.got_subcommand("view")) return view();
        if (app.got_subcommand("thumbnail")) return thumbnail();
        if (app.got_subcommand("views")) return views();
        if (app.got_subcommand("completion")) return completion();
    } catch (const InputError& e) {
        std::cerr << "softraster: error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "softraster: internal error: " << e.what() << "\n";
        return 1;
    }
    return 1;
}

}  // namespace softraster::cli
