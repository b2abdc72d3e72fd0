// Microbenchmarks of single stages: triangle setup, traversal (rasterization), fragment
// shading and the MSAA resolve.  build-release/bench/micro_benchmarks
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/context.h"
#include "softraster/shading/surface_shader.h"

using namespace softraster;

namespace {

constexpr int N = 9;  // a lit, textured, colored surface

template <int M = N>
ShadedVertex<M> vertex(float x, float y, float w = 1.0f) {
    ClipVertex<M> c{glm::vec4((2 * x / 1920 - 1), (1 - 2 * y / 1080), 0.2f, w), {}};
    for (int k = 0; k < M; ++k) c.var[size_t(k)] = float(k) * 0.1f + x * 0.001f;
    ShadedVertex<M> v;
    finish_vertex(c, Viewport{1920, 1080}, v);
    return v;
}

// (AVX2 code, as in the back end)
[[gnu::noinline]] SOFTRASTER_AVX2_TARGET bool setup_avx2(const ShadedVertex<N>& a, const ShadedVertex<N>& b, const ShadedVertex<N>& c,
                                                        const Rect& tile, TriangleSetup<N>& t) {
    return setup_triangle<1>(a, b, c, FrontFace::CCW, tile, t);
}
void BM_TriangleSetup(benchmark::State& state) {
    const ShadedVertex<N> a = vertex(100.3f, 100.7f), b = vertex(103.9f, 101.2f), c = vertex(101.1f, 104.6f);
    TriangleSetup<N> t;
    const Rect tile{64, 64, 128, 128};
    for (auto _ : state) {
        benchmark::DoNotOptimize(setup_avx2(a, b, c, tile, t));
        benchmark::ClobberMemory();
    }
}
BENCHMARK(BM_TriangleSetup);

// The interpolation planes alone (setup_planes), by varying count: N + 2 planes in double.
template <int M>
[[gnu::noinline]] SOFTRASTER_AVX2_TARGET void planes_avx2(TriangleSetup<M>& t) {
    setup_planes(t);
}
template <int M>
void BM_SetupPlanes(benchmark::State& state) {
    // (w varies, so 1/w and every varying/w have gradients)
    const ShadedVertex<M> a = vertex<M>(100.3f, 100.7f, 1.1003f), b = vertex<M>(103.9f, 101.2f, 1.1039f),
                          c = vertex<M>(101.1f, 104.6f, 1.1011f);
    TriangleSetup<M> t;
    if (!setup_coverage<1>(a, b, c, FrontFace::CCW, Rect{128, 128, 192, 192}, t)) state.SkipWithError("outside");
    for (auto _ : state) {
        planes_avx2<M>(t);
        benchmark::ClobberMemory();
    }
}
BENCHMARK(BM_SetupPlanes<3>);
BENCHMARK(BM_SetupPlanes<6>);
BENCHMARK(BM_SetupPlanes<9>);

// Covered samples of a triangle filling half of a 64x64 tile (or a small one).
template <int Samples>
void BM_Traversal(benchmark::State& state) {
    const float size = float(state.range(0));
    const ShadedVertex<N> a = vertex(64.2f, 64.4f), b = vertex(64.2f + size, 64.9f), c = vertex(64.6f, 64.1f + size);
    TriangleSetup<N> t;
    setup_triangle<Samples>(a, b, c, FrontFace::CCW, Rect{64, 64, 128, 128}, t);
    int64_t pixels = 0;
    for (auto _ : state) {
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) { pixels += px.mask; });
        benchmark::DoNotOptimize(pixels);
    }
    state.SetItemsProcessed(state.iterations() * int64_t(size * size / 2));
}
BENCHMARK(BM_Traversal<1>)->Arg(2)->Arg(8)->Arg(63);
BENCHMARK(BM_Traversal<4>)->Arg(2)->Arg(8)->Arg(63);

// The same in groups of eight pixels, as the back end walks them (AVX2 code, as there):
// row spans (rasterization.h) and the 32-bit path for small triangles (rasterization_small.h).
SOFTRASTER_AVX2_TARGET int64_t covered_by_spans(const TriangleSetup<N>& t) {
    simd::i8 lanes{};
    rasterize_spans(t, t.bounds, [&](int, int x_begin, int x_end) {
        simd::for_each_group(x_begin, x_end, [&](int, simd::i8 covered) { lanes -= covered; });
    });
    int64_t n = 0;
    for (int l = 0; l < simd::kLanes; ++l) n += lanes[l];
    return n;
}
template <int Samples>
SOFTRASTER_AVX2_TARGET int64_t covered_small(const TriangleSetup<N>& t) {
    simd::i8 lanes{};
    rasterize_small<Samples>(t, [&](int, int, const auto& covered) {
        for (const simd::i8& c : covered) lanes -= c;
    });
    int64_t n = 0;
    for (int l = 0; l < simd::kLanes; ++l) n += lanes[l];
    return n;
}
template <int Samples, bool Small>
void BM_TraversalGroups(benchmark::State& state) {
    const float size = float(state.range(0));
    const ShadedVertex<N> a = vertex(64.2f, 64.4f), b = vertex(64.2f + size, 64.9f), c = vertex(64.6f, 64.1f + size);
    TriangleSetup<N> t;
    setup_triangle<Samples>(a, b, c, FrontFace::CCW, Rect{64, 64, 128, 128}, t);
    for (auto _ : state) {
        if constexpr (Small) benchmark::DoNotOptimize(covered_small<Samples>(t));
        else benchmark::DoNotOptimize(covered_by_spans(t));
    }
    state.SetItemsProcessed(state.iterations() * int64_t(size * size / 2));
}
BENCHMARK(BM_TraversalGroups<1, false>)->Arg(2)->Arg(8)->Arg(63);
BENCHMARK(BM_TraversalGroups<1, true>)->Arg(2)->Arg(8)->Arg(63);
BENCHMARK(BM_TraversalGroups<4, true>)->Arg(2)->Arg(8)->Arg(63);

template <Shading M>
void BM_Shading(benchmark::State& state) {
    SurfaceUniforms u;
    u.lights.count = 2;
    u.lights.to_light[0] = glm::normalize(glm::vec3(1, 1, 1));
    u.lights.to_light[1] = glm::normalize(glm::vec3(-1, 0.5f, 1));
    u.lights.color[0] = u.lights.color[1] = glm::vec3(0.7f);
    const SurfaceShader<M, false, false> shader{&u};
    typename SurfaceShader<M, false, false>::Varyings v{};
    if constexpr (decltype(v)::kNormal) v.normal = glm::vec3(0.1f, 0.2f, 0.9f);
    glm::vec4 color;
    for (auto _ : state) {
        benchmark::DoNotOptimize(shader.fragment(v, FragCoord{}, color));
        benchmark::DoNotOptimize(color);
    }
}
BENCHMARK(BM_Shading<Shading::Lambert>);
BENCHMARK(BM_Shading<Shading::BlinnPhong>);

void BM_TextureBilinear(benchmark::State& state) {
    Image img(256, 256);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Rgba8{uint8_t(i), uint8_t(i >> 3), uint8_t(i >> 6), 255};
    const Texture tex(img);
    float u = 0.1f;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tex.sample(glm::vec2(u, 0.3f), Filter::Bilinear, Wrap::Repeat));
        u += 0.001f;
    }
}
BENCHMARK(BM_TextureBilinear);

// Eight trilinear lookups at once (Texture::sample8) across a 1024x1024 texture, a row of a
// minified wall: about two levels down, the levels' texels warm in the cache. The
// arithmetic of the lookup alone, without the pipeline around it.
template <bool Chained>
void BM_TextureTrilinear8(benchmark::State& state) {
    Image img(1024, 1024);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Rgba8{uint8_t(i), uint8_t(i >> 3), uint8_t(i >> 6), 255};
    const Texture tex(img);
    const Sampler s{Filter::Bilinear, Filter::Bilinear, MipFilter::Linear, Wrap::Repeat, Wrap::Repeat, glm::vec4(0.0f), 1};
    const float du = 5.3f / 1024.0f;  // texels per pixel: a level of detail of about 2.4
    const std::array<simd::f8, 4> d{simd::splat(du), simd::splat(0.0f), simd::splat(0.0f), simd::splat(du * 0.4f)};
    simd::f8 u, v = simd::splat(0.3f);
    for (int k = 0; k < simd::kLanes; ++k) u[k] = float(k) * du;
    std::array<simd::f8, 4> rgba;
    for (auto _ : state) {
        tex.sample8(u, v, d, s, rgba);
        benchmark::DoNotOptimize(rgba);
        u = u + 8.0f * du, v = v + 0.0007f;
        if constexpr (Chained) u = u + rgba[0] * 0.0f;  // (each lookup waits for the one before)
        if (u[0] > 64.0f) u = u - 64.0f;  // (the texel coordinates stay exact)
    }
    state.SetItemsProcessed(state.iterations() * simd::kLanes);
}
BENCHMARK(BM_TextureTrilinear8<false>);
BENCHMARK(BM_TextureTrilinear8<true>);

// The same lookups two groups at a time, as the fragment shader asks for them: a row of
// quads' two pixel rows, one level of detail for both (Texture::sample_pair).
void BM_TextureTrilinearRows(benchmark::State& state) {
    Image img(1024, 1024);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Rgba8{uint8_t(i), uint8_t(i >> 3), uint8_t(i >> 6), 255};
    const Texture tex(img);
    const Sampler s{Filter::Bilinear, Filter::Bilinear, MipFilter::Linear, Wrap::Repeat, Wrap::Repeat, glm::vec4(0.0f), 1};
    const float du = 5.3f / 1024.0f;
    const std::array<simd::f8, 4> d{simd::splat(du), simd::splat(0.0f), simd::splat(0.0f), simd::splat(du * 0.4f)};
    simd::f8 u, v0 = simd::splat(0.3f), v1 = simd::splat(0.3f + du * 0.4f);
    for (int k = 0; k < simd::kLanes; ++k) u[k] = float(k) * du;
    std::array<simd::f8, 4> rgba0, rgba1;
    for (auto _ : state) {
        tex.sample_pair(u, v0, u, v1, d, d, s, rgba0, rgba1);
        benchmark::DoNotOptimize(rgba0), benchmark::DoNotOptimize(rgba1);
        u = u + 8.0f * du, v0 = v0 + 0.0007f, v1 = v1 + 0.0007f;
        if (u[0] > 64.0f) u = u - 64.0f;
    }
    state.SetItemsProcessed(state.iterations() * 2 * simd::kLanes);
}
BENCHMARK(BM_TextureTrilinearRows);

void BM_Resolve(benchmark::State& state) {
    Framebuffer fb(1920, 1080, int(state.range(0)));
    fb.clear_color(glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    for (auto _ : state) benchmark::DoNotOptimize(fb.read_pixels());
    state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}
BENCHMARK(BM_Resolve)->Arg(1)->Arg(4);

// The clear, tile by tile as the tile loop runs it, over framebuffers that together exceed
// the last-level cache (as a frame's own data evicts its framebuffer).
void BM_ClearTiles(benchmark::State& state) {
    std::vector<Framebuffer> fbs;
    for (int i = 0; i < 4; ++i) fbs.emplace_back(1920, 1080, int(state.range(0)));
    DrawTarget target;
    target.grid = TileGrid(1920, 1080);
    ClearCommand clear(glm::vec4(0.1f, 0.2f, 0.3f, 1.0f), 1.0f);
    size_t f = 0;
    for (auto _ : state) {
        target.fb = &fbs[f++ % fbs.size()];
        for (int tile = 0; tile < target.grid.count(); ++tile) clear.draw_tile(tile, target.grid.tile_rect(tile), target);
        benchmark::ClobberMemory();
    }
}
BENCHMARK(BM_ClearTiles)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

}  // namespace
