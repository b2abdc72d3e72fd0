// glref: renders a scene file (format version 1) with Mesa's llvmpipe through OSMesa, the
// test suite's independent reference. Test-only; see docs/conformance.md.
//
//   glref SCENE.json -o OUT.png
//   glref SCENE.json --time --frames 20 --warmup 3     (one JSON line; LP_NUM_THREADS respected)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "gl_scene.h"
#include "osmesa_target.h"
#include "softraster/error.h"
#include "softraster/io/image_io.h"

int main(int argc, char** argv) {
    CLI::App app{"glref: render a scene with Mesa llvmpipe (OSMesa), the test reference"};
    std::string scene_path, out;
    bool time_mode = false;
    int frames = 20, warmup = 3;
    app.add_option("scene", scene_path, "Scene file (.json)")->required();
    app.add_option("-o,--output", out, "Output PNG");
    app.add_flag("--time", time_mode, "Time frames instead of writing a picture; prints one JSON line");
    app.add_option("--frames", frames, "Timed frames")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", warmup, "Untimed frames first")->check(CLI::Range(0, 100000));
    CLI11_PARSE(app, argc, argv);
    try {
        const softraster::Scene scene = softraster::load_scene(scene_path);
        glref::OsmesaTarget target(scene.width, scene.height, scene.samples);
        const glref::GlScene gl_scene(scene);
        if (!time_mode) {
            if (out.empty()) throw softraster::InputError("glref: -o OUT.png is required");
            target.bind_for_drawing();
            gl_scene.draw_frame();
            target.resolve();
            glFinish();
            softraster::write_png(target.read_pixels(), out);
            return 0;
        }
        std::vector<double> ms;
        for (int i = 0; i < warmup + frames; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            target.bind_for_drawing();
            gl_scene.draw_frame();
            target.resolve();
            glFinish();
            const double dt = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (i >= warmup) ms.push_back(dt);
        }
        std::sort(ms.begin(), ms.end());
        const char* env = std::getenv("LP_NUM_THREADS");
        const int threads = env ? std::atoi(env) : int(std::thread::hardware_concurrency());
        std::printf("{\"renderer\": \"llvmpipe\", \"gl_renderer\": \"%s\", \"scene\": \"%s\", \"threads\": %d, \"frames\": %d, "
                    "\"median_ms\": %.3f, \"min_ms\": %.3f, \"max_ms\": %.3f}\n",
                    target.renderer().c_str(), scene_path.c_str(), threads, frames, ms[ms.size() / 2], ms.front(), ms.back());
        return 0;
    } catch (const softraster::InputError& e) {
        std::cerr << "glref: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "glref: " << e.what() << "\n";
        return 1;
    }
}
