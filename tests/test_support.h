// Shared helpers for the unit tests: tiny shaders that take clip-space positions directly.
#pragma once
#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <span>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "softraster/context.h"
#include "softraster/error.h"

namespace softraster::test {

// The message of the InputError that f throws, or "" when it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Each component of a within eps of b's.
inline void expect_near(const glm::vec3& a, const glm::vec3& b, float eps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// Vertex = clip-space position + one scalar attribute; the fragment color is a constant.
struct ClipVertexIn {
    glm::vec4 clip;
    float value = 0;
};

struct ValueVaryings {
    float value;
};

struct ConstantColorShader {
    using Vertex = ClipVertexIn;
    using Varyings = ValueVaryings;
    glm::vec4 color{1.0f};
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.value = in.value;
        return in.clip;
    }
    bool fragment(const Varyings&, const FragCoord&, glm::vec4& c) const {
        c = color;
        return true;
    }
};

// Writes the interpolated value to red (as value / 255 would be lossy, tests read it back
// through a capture instead: see CaptureShader).
struct CaptureShader {
    using Vertex = ClipVertexIn;
    using Varyings = ValueVaryings;
    std::vector<float>* values;  // width * height, written per shaded pixel
    int width;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.value = in.value;
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord& f, glm::vec4& c) const {
        (*values)[size_t(int(f.y) * width + int(f.x))] = v.value;
        c = glm::vec4(1.0f);
        return true;
    }
};

// Window position (pixels, y down) and depth -> clip coordinates with w = 1.
inline glm::vec4 window_to_clip(float x, float y, int width, int height, float z = 0.5f, float w = 1.0f) {
    return glm::vec4((2.0f * x / float(width) - 1.0f) * w, (1.0f - 2.0f * y / float(height)) * w, (2.0f * z - 1.0f) * w, w);
}

// Three post-transform vertices at random within sx by sy pixels around (cx, cy) of a
// 256x256 viewport (one varying, unused). False if one cannot be mapped to the window.
inline bool random_triangle(std::mt19937& rng, float cx, float cy, float sx, float sy, std::array<ShadedVertex<1>, 3>& out) {
    std::uniform_real_distribution<float> u(0, 1);
    for (auto& v : out) {
        const float x = cx + sx * (u(rng) - 0.5f);
        const float y = cy + sy * (u(rng) - 0.5f);
        if (!finish_vertex(ClipVertex<1>{window_to_clip(x, y, 256, 256), {}}, Viewport{256, 256}, v)) return false;
    }
    return true;
}

// Writes `contents` to <temp>/<folder>/<name> and returns the path.
inline std::filesystem::path write_temp_file(const std::string& folder, const std::string& name, const std::string& contents) {
    // One folder per process: ctest runs the tests of a program in parallel processes, and
    // two of them writing the same name would read each other's file.
    const auto dir = std::filesystem::temp_directory_path() / (folder + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary) << contents;
    return path;
}

// Two triangles per cell of an n x n grid of (n + 1)^2 row-major vertices; diagonal(a) picks,
// for cell corner a, whether the cell is split along a-c (true) or b-d.
template <class Diagonal>
std::vector<uint32_t> grid_indices(int n, Diagonal&& diagonal) {
    std::vector<uint32_t> idx;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 2, d = a + uint32_t(n) + 1;
            if (diagonal(a)) idx.insert(idx.end(), {a, b, c, a, c, d});
            else idx.insert(idx.end(), {a, b, d, b, c, d});
        }
    return idx;
}

// Sets a context up to count coverage: cleared to black, no culling, no depth test, additive
// blending (each fragment adds its color times its alpha to what is stored).
inline void count_coverage(Context& ctx) {
    ctx.clear(glm::vec4(0, 0, 0, 1));
    ctx.state.cull = CullMode::None;
    ctx.state.depth_test = false;
    ctx.state.blend = BlendMode::Additive;
}

template <class S>
void draw(Context& ctx, const S& shader, const std::vector<typename S::Vertex>& v, const std::vector<uint32_t>& idx,
          Topology t = Topology::Triangles) {
    ctx.draw(t, shader, std::span<const typename S::Vertex>(v), std::span<const uint32_t>(idx));
    ctx.finish();
}


// A vertex-color shader that a test marks pure (kPure: never discards, no side effects) or
// not, to compare the paths only pure shaders take (hidden-surface removal, the fragment
// queue) with the plain one. It shades one or eight fragments; back faces flip blue.
struct RgbVertex {
    glm::vec4 clip;
    glm::vec3 color;
};
struct RgbVaryings {
    float r, g, b;
};
template <bool Pure>
struct RgbShader {
    using Vertex = RgbVertex;
    using Varyings = RgbVaryings;
    static constexpr bool kPure = Pure;
    std::atomic<uint64_t>* batch_calls = nullptr;  // counts fragment_batch calls, if set
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out = {in.color.r, in.color.g, in.color.b};
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord& f, glm::vec4& c) const {
        c = glm::vec4(v.r, v.g, f.front_facing ? v.b : 1.0f - v.b, 1.0f);
        return true;
    }
    void fragment_batch(const std::array<simd::f8, 3>& v, simd::f8, bool front_facing, std::array<simd::f8, 4>& c) const {
        if (batch_calls) batch_calls->fetch_add(1, std::memory_order_relaxed);
        c = {v[0], v[1], front_facing ? v[2] : 1.0f - v[2], simd::splat(1.0f)};
    }
};

struct RgbMesh {
    std::vector<RgbVertex> vertices;
    std::vector<uint32_t> indices;
};

// Depth functions (with a clear depth that lets something pass) that keep the nearer, the
// farther, ties, or everything.
struct DepthCase {
    DepthFunc func;
    float clear;
};
inline const std::array<DepthCase, 4> kDepthCases = {
    {{DepthFunc::Less, 1.0f}, {DepthFunc::LessEqual, 1.0f}, {DepthFunc::Greater, 0.0f}, {DepthFunc::Always, 1.0f}}};

// Every sample's color and depth after drawing `meshes` in order (two threads, no culling;
// with stencil_always, a stencil test that every fragment passes and that changes nothing,
// which sends the draws to the general back end's command; `batching`, how the context splits
// the draws into batches).
struct SamplePicture {
    std::vector<Rgba8> color;
    std::vector<float> depth;
    uint64_t shaded = 0;  // fragments shaded
    size_t batches = 0;   // the context's batches
};
template <bool Pure>
SamplePicture draw_rgb_meshes(int width, int height, int samples, DepthCase depth, const std::vector<RgbMesh>& meshes,
                              std::atomic<uint64_t>* batch_calls = nullptr, bool stencil_always = false,
                              Context::Batching batching = {}) {
    Framebuffer fb(width, height, samples);
    WorkerPool pool(2);
    Context ctx(fb, &pool);
    ctx.batching = batching;
    ctx.clear(glm::vec4(0, 0, 0, 1), depth.clear);
    ctx.state.cull = CullMode::None;
    ctx.state.depth_func = depth.func;
    ctx.state.stencil_test = stencil_always;  // (the default faces: always pass, keep)
    for (const RgbMesh& m : meshes)
        ctx.draw(Topology::Triangles, RgbShader<Pure>{batch_calls}, std::span<const RgbVertex>(m.vertices), std::span<const uint32_t>(m.indices));
    ctx.execute();
    const size_t n = size_t(width) * size_t(height) * size_t(samples);
    return {std::vector<Rgba8>(fb.color_data(), fb.color_data() + n), std::vector<float>(fb.depth_data(), fb.depth_data() + n),
            ctx.fragments_shaded(), ctx.batches()};
}

// The pipelines of the shaders most tests share are compiled once, in test_support.cpp, not
// in every test file that draws with them (each copy of a pipeline costs seconds of build).
// (Function templates: an explicit instantiation declaration does not stop an inline
// function, such as Context::draw, from being compiled again where it is called.)
extern template void draw<ConstantColorShader>(Context&, const ConstantColorShader&, const std::vector<ClipVertexIn>&,
                                               const std::vector<uint32_t>&, Topology);
extern template SamplePicture draw_rgb_meshes<true>(int, int, int, DepthCase, const std::vector<RgbMesh>&, std::atomic<uint64_t>*, bool,
                                                   Context::Batching);
extern template SamplePicture draw_rgb_meshes<false>(int, int, int, DepthCase, const std::vector<RgbMesh>&, std::atomic<uint64_t>*, bool,
                                                    Context::Batching);

}  // namespace softraster::test
