// glref: renders a scene file (format versions 1 and 2) with Mesa's llvmpipe through OSMesa, the
// test suite's independent reference. Test-only; see docs/conformance.md.
//
//   glref SCENE.json -o OUT.png
//   glref SCENE.json --time --frames 20 --warmup 3     (one JSON line; LP_NUM_THREADS respected)
#include <algorithm>
#include <chrono>
#include <cmath>
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

// sRGB's transfer function, written out here in double precision (the reference does not
// use softraster's tables).
double srgb_decode(uint8_t k) {
    const double c = k / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
uint8_t srgb_encode(double l) {
    l = std::clamp(l, 0.0, 1.0);
    const double c = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return uint8_t(std::floor(255.0 * c + 0.5));
}

// Each output channel: floor(mean + 0.5) of the k x k block's 8-bit values (sRGB pictures:
// r, g, b averaged in linear light).
softraster::Image box_filter(const softraster::Image& in, int k, bool srgb) {
    softraster::Image out(in.width / k, in.height / k);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            if (srgb) {  // in linear light: the mean of the decoded values, encoded
                double sum[3] = {0, 0, 0};
                int alpha = 0;
                for (int j = 0; j < k; ++j)
                    for (int i = 0; i < k; ++i) {
                        const softraster::Rgba8 c = in.pixels[size_t((y * k + j) * in.width + x * k + i)];
                        sum[0] += srgb_decode(c.r), sum[1] += srgb_decode(c.g), sum[2] += srgb_decode(c.b);
                        alpha += c.a;
                    }
                const int n = k * k;
                out.pixels[size_t(y * out.width + x)] = {srgb_encode(sum[0] / n), srgb_encode(sum[1] / n), srgb_encode(sum[2] / n),
                                                         uint8_t((alpha + n / 2) / n)};
                continue;
            }
            int sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const softraster::Rgba8 c = in.pixels[size_t((y * k + j) * in.width + x * k + i)];
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b, sum[3] += c.a;
                }
            const int n = k * k;
            out.pixels[size_t(y * out.width + x)] = {uint8_t((sum[0] + n / 2) / n), uint8_t((sum[1] + n / 2) / n),
                                                     uint8_t((sum[2] + n / 2) / n), uint8_t((sum[3] + n / 2) / n)};
        }
    return out;
}

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
        // Supersampling: drawn at k times the size, then box-filtered here (below).
        const int k = scene.supersample;
        const bool srgb = scene.color_space == softraster::ColorSpace::Srgb;
        glref::OsmesaTarget target(scene.width * k, scene.height * k, scene.samples, srgb);
        const glref::GlScene gl_scene(scene);
        if (!time_mode) {
            if (out.empty()) throw softraster::InputError("glref: -o OUT.png is required");
            target.bind_for_drawing();
            gl_scene.draw_frame();
            target.resolve();
            glFinish();
            softraster::Image picture = target.read_pixels();
            gl_scene.apply_ambient_occlusion(picture);
            softraster::write_png(box_filter(picture, k, srgb), out);
            return 0;
        }
        std::vector<double> ms;
        for (int i = 0; i < warmup + frames; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            target.bind_for_drawing();
            gl_scene.draw_frame();
            target.resolve();
            if (scene.ambient_occlusion) {
                softraster::Image picture = target.read_pixels();
                gl_scene.apply_ambient_occlusion(picture);
            }
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
