// Determinism: the picture is byte-identical whatever the number of threads, because each
// tile is drawn by one thread at a time, in draw order, from bins that keep draw order.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "softraster/scene/scene_renderer.h"

using namespace softraster;

namespace {
#ifdef SOFTRASTER_UNDER_SANITIZERS
constexpr bool kUnderSanitizers = true;
#else
constexpr bool kUnderSanitizers = false;
#endif

std::vector<std::filesystem::path> scenes() {
    std::vector<std::filesystem::path> out;
    for (const char* dir : {"conformance", "scenes"})
        for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(SOFTRASTER_TEST_DATA) / dir))
            if (e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

TEST(Determinism, SamePictureAt1To8Threads) {
    const auto files = scenes();
    ASSERT_GT(files.size(), 20u);
    // Under the sanitizers (unoptimized, many times slower) three threads only, on the
    // generic path (the next test's work, folded in): that build looks for memory errors in
    // threaded draws and in both copies of the pipeline, the Release build checks the
    // properties one by one.
    const std::vector<unsigned> counts = kUnderSanitizers ? std::vector<unsigned>{3} : std::vector<unsigned>{2, 3, 8};
    for (const auto& f : files) {
        const Scene scene = load_scene(f);
        const Image one = SceneRenderer(scene, 1).render();
        for (unsigned threads : counts) {
            simd::use_generic_path(kUnderSanitizers);
            const Image many = SceneRenderer(scene, threads).render();
            simd::use_generic_path(false);
            EXPECT_TRUE(one.pixels == many.pixels) << f.filename() << " differs at " << threads << " threads";
        }
    }
}

TEST(Determinism, SamePictureOnEveryCpuPath) {
    if (kUnderSanitizers) GTEST_SKIP() << "under the sanitizers, SamePictureAt1To8Threads draws on both paths";
    simd::use_generic_path(false);
    if (!simd::wide_path_runs()) GTEST_SKIP() << "no AVX2 path here (this CPU, or a SOFTRASTER_GENERIC_ONLY build): only the generic path runs";
    for (const auto& f : scenes()) {
        const Scene scene = load_scene(f);
        simd::use_generic_path(true);
        const Image generic = SceneRenderer(scene, 2).render();
        simd::use_generic_path(false);
        const Image fast = SceneRenderer(scene, 2).render();
        EXPECT_TRUE(generic.pixels == fast.pixels) << f.filename();
        if (simd::cpu_has_avx512()) {  // (and the common texture lookup's AVX-512 copy off: all AVX2)
            simd::use_avx512(false);
            const Image avx2 = SceneRenderer(scene, 2).render();
            simd::use_avx512(true);
            EXPECT_TRUE(avx2.pixels == fast.pixels) << f.filename() << " with AVX-512 and without";
        }
        // Something was drawn: more than the background's one color.
        EXPECT_NE(std::adjacent_find(fast.pixels.begin(), fast.pixels.end(), std::not_equal_to<>()), fast.pixels.end()) << f.filename();
    }
}

TEST(Determinism, ReplayingAFrameGivesTheSamePicture) {
    const Scene scene = showcase_scene();
    const SceneRenderer renderer(scene, 2);
    Framebuffer fb(scene.width, scene.height, scene.samples);
    renderer.render(fb);
    const Image first = fb.read_pixels();
    renderer.render(fb);
    EXPECT_TRUE(first.pixels == fb.read_pixels().pixels);
}
