#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/pipeline/simd.h"
#include "softraster/scene/animation.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {

namespace {
// The CPU copies the frames ran on (pipeline/simd.h), so that times taken on one machine
// with SOFTRASTER_GENERIC or SOFTRASTER_NO_AVX512 set, or on another CPU, say so.
const char* cpu_path() {
    if (simd::cpu_has_avx512()) return "avx512";  // (the texture lookup's and the sRGB encode's; the rest AVX2)
    return simd::wide_path_runs() ? "avx2" : "generic";
}

// One frame as bench times it: every draw, and with MSAA the resolve (llvmpipe's timing
// blits to a resolve buffer too; single-sampled, the framebuffer already is the picture),
// and a supersampled scene's downsampling.
RenderStats draw_frame(const Scene& scene, const SceneRenderer& renderer, Framebuffer& fb, Image& picture) {
    const RenderStats stats = renderer.render(fb);
    if (fb.samples() > 1) resolve(fb, picture, renderer.pool());
    if (scene.supersample > 1) picture = downsample_box(fb.samples() > 1 ? picture : fb.read_pixels(), scene.supersample);
    return stats;
}
double median_of(std::vector<double> ms) {
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

// --scaling: the same frames on one thread and on `threads`, taking turns frame by frame, so
// that a stretch of the machine's time that runs slow (a shared machine's neighbours) falls
// on both alike; times taken seconds apart in two runs compare the machine's moments as much
// as the thread counts (docs/performance.md, "The second thread, measured in one process").
int run_scaling(const BenchOptions& opt, const Scene& scene, unsigned threads) {
    const SceneRenderer renderers[2] = {SceneRenderer(scene, 1), SceneRenderer(scene, threads)};
    Framebuffer fbs[2] = {renderers[0].make_framebuffer(), renderers[1].make_framebuffer()};
    Image picture(scene.width, scene.height);
    std::vector<double> ms[2];
    for (int i = 0; i < 2 * (opt.warmup + opt.frames); ++i) {
        const int k = i % 2;
        const auto t0 = std::chrono::steady_clock::now();
        draw_frame(scene, renderers[k], fbs[k], picture);
        const auto t1 = std::chrono::steady_clock::now();
        if (i >= 2 * opt.warmup) ms[k].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    const double one = median_of(ms[0]), many = median_of(ms[1]);
    const double min_one = *std::min_element(ms[0].begin(), ms[0].end()), min_many = *std::min_element(ms[1].begin(), ms[1].end());
    if (opt.json) {
        std::printf("{\"renderer\": \"softraster\", \"scene\": \"%s\", \"threads\": %u, \"frames\": %d, \"median_ms\": %.3f, "
                    "\"min_ms\": %.3f, \"one_thread_median_ms\": %.3f, \"one_thread_min_ms\": %.3f, \"speedup\": %.3f, \"cpu_path\": \"%s\"}\n",
                    opt.scene.c_str(), threads, opt.frames, many, min_many, one, min_one, one / many, cpu_path());
    } else {
        std::printf("%s: %dx%d, %d sample(s), 1 and %u threads taking turns, %d frames each after %d warm-up, %s code\n", opt.scene.c_str(),
                    scene.width, scene.height, scene.samples, threads, opt.frames, opt.warmup, cpu_path());
        std::printf("  1 thread:   median %.2f ms   min %.2f ms\n", one, min_one);
        std::printf("  %u threads: median %.2f ms   min %.2f ms\n", threads, many, min_many);
        std::printf("  %.2fx as fast on %u threads (median frames)\n", one / many, threads);
        // (More than the thread count: the cores did not run at one speed, say a virtual
        // machine's core slowed by its host, which taking turns does not even out.)
        if (one / many > 1.05 * threads) std::printf("  (more than %u times: the cores ran at different speeds meanwhile; run it again)\n", threads);
    }
    return 0;
}
}  // namespace

int run_bench(const BenchOptions& opt) {
    const Scene scene = load_scene(opt.scene);
    const unsigned threads = thread_count(opt.threads);
    if (opt.scaling) {
        if (threads < 2) {
            std::fprintf(stderr, "softraster bench: --scaling compares 1 thread with more: give --threads 2 or more (this machine has %u core(s))\n",
                         std::max(1u, std::thread::hardware_concurrency()));
            return 2;
        }
        return run_scaling(opt, scene, threads);
    }
    std::optional<SceneRenderer> still;  // without --orbit one renderer draws every frame
    if (!opt.orbit) still.emplace(scene, threads);
    std::optional<Framebuffer> fb;  // made by the first frame's renderer, drawn into by all
    std::vector<double> ms;
    RenderStats stats;
    size_t triangles = 0;
    Image picture(scene.width, scene.height);
    auto timed_start = std::chrono::steady_clock::now(), timed_end = timed_start;
    for (int i = 0; i < opt.warmup + opt.frames; ++i) {
        if (i == opt.warmup) timed_start = std::chrono::steady_clock::now();
        const auto t0 = std::chrono::steady_clock::now();
        std::optional<Scene> turned_copy;  // (declared first: the renderer keeps a reference to it)
        std::optional<SceneRenderer> turned;
        if (opt.orbit) turned.emplace(turned_copy.emplace(turned_scene(scene, 360.0 * std::max(0, i - opt.warmup) / opt.frames)), threads);
        const SceneRenderer& renderer = opt.orbit ? *turned : *still;
        if (!fb) fb.emplace(renderer.make_framebuffer());
        stats = draw_frame(scene, renderer, *fb, picture);
        timed_end = std::chrono::steady_clock::now();
        if (i >= opt.warmup) ms.push_back(std::chrono::duration<double, std::milli>(timed_end - t0).count());
        // A statistic, counted once, outside the frames' time (a walk over every draw's mesh).
        if (i + 1 == opt.warmup + opt.frames) triangles = renderer.triangle_count();
    }
    const double fps = opt.frames / std::chrono::duration<double>(timed_end - timed_start).count();
    std::sort(ms.begin(), ms.end());
    const double median = ms[ms.size() / 2];
    const double tris_per_s = double(triangles) / (median / 1000.0);
    const double frags_per_s = double(stats.fragments_shaded) / (median / 1000.0);
    if (opt.json) {
        std::printf("{\"renderer\": \"softraster\", \"scene\": \"%s\", \"threads\": %u, \"frames\": %d, \"median_ms\": %.3f, "
                    "\"min_ms\": %.3f, \"max_ms\": %.3f, \"triangles\": %zu, \"triangles_per_s\": %.0f, "
                    "\"fragments_shaded\": %llu, \"fragments_per_s\": %.0f, \"orbit\": %s, \"fps\": %.2f, \"cpu_path\": \"%s\"}\n",
                    opt.scene.c_str(), threads, opt.frames, median, ms.front(), ms.back(), triangles, tris_per_s,
                    static_cast<unsigned long long>(stats.fragments_shaded), frags_per_s, opt.orbit ? "true" : "false", fps, cpu_path());
    } else {
        std::printf("%s: %dx%d, %d sample(s), %zu triangles, %u thread(s), %d frames after %d warm-up, %s code\n",
                    opt.scene.c_str(), scene.width, scene.height, scene.samples, triangles, threads, opt.frames, opt.warmup, cpu_path());
        std::printf("  median %.2f ms   min %.2f ms   max %.2f ms   %.1f frames/s%s\n", median, ms.front(), ms.back(), fps,
                    opt.orbit ? " (one turn)" : "");
        std::printf("  %.1f M triangles/s   %.1f M fragments shaded/s (%llu per frame)\n", tris_per_s / 1e6,
                    frags_per_s / 1e6, static_cast<unsigned long long>(stats.fragments_shaded));
    }
    return 0;
}

}  // namespace softraster::cli
