// The recorded commands a Context executes: a clear, and draws of triangles, lines and
// points. Each runs in three phases, every phase over all commands in parallel:
//   1. vertex processing, in chunks of vertices;
//   2. primitive assembly, clipping, culling and binning, in chunks of primitives
//      (a draw of one chunk of each does 1 and 2 as one item, see Context::execute);
//   3. per tile, in draw order: triangle setup, rasterization, fragment shading, output merge.
// A command is one virtual call per chunk or per tile; everything per pixel inside it is a
// template specialized for the shader, the sample count and the blend mode.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/hidden_surface_removal.h"
#include "softraster/pipeline/line_rasterization.h"

namespace softraster {

// Where commands draw during one execution.
struct Target {
    Framebuffer* fb = nullptr;
    TileGrid grid;
    ClipPlanes planes;  // with the guard band for this viewport
    Viewport viewport;
};

class Command {
public:
    virtual ~Command() = default;
    // Sizes the command's buffers (sequentially, before the parallel phases).
    virtual void prepare() {}
    virtual size_t vertex_chunks() const { return 0; }
    virtual void process_vertex_chunk(size_t, const Target&) {}
    virtual size_t primitive_chunks() const { return 0; }
    virtual void bin_primitive_chunk(size_t, const Target&) {}
    // After all chunks are binned (sequentially): the per-tile totals below.
    virtual void finish_binning(const TileGrid&) {}
    // Draws this command's part of one tile; returns the fragments shaded.
    virtual uint64_t draw_tile(int tile, const Rect& rect, const Target&) = 0;

    // A binned command with nothing in the tile: the tile loop passes it by without a call
    // (a scene of many small objects has most of its draws absent from most tiles).
    bool skips_tile(int tile) const { return binned() && tile_triangles_[size_t(tile)] == 0; }
    size_t triangles_in_tile(int tile) const { return binned() ? tile_triangles_[size_t(tile)] : 0; }
    // Pixels of the tile this command's triangles cover, summed (each triangle's area, at
    // most its bounding box within the tile): an estimate of the overdraw.
    double covered_area(int tile) const { return binned() ? tile_area_[size_t(tile)] : 0.0; }

    // Hidden-surface removal (hidden_surface_removal.h), for commands that allow it.
    bool allows_hidden_surface_removal() const { return allows_hsr_; }
    virtual void visibility_pass(int, const Rect&, const Target&, uint32_t /*draw*/, uint32_t* /*owners*/) {}
    virtual uint64_t shading_pass(int, const Rect&, const Target&, uint32_t /*draw*/, const uint32_t* /*owners*/) { return 0; }

protected:
    bool allows_hsr_ = false;
    // Filled by finish_binning of commands binned by tile (empty for the others).
    bool binned() const { return !tile_triangles_.empty(); }
    std::vector<uint32_t> tile_triangles_;
    std::vector<double> tile_area_;
};

class ClearCommand final : public Command {
public:
    ClearCommand(const glm::vec4& color, float depth) : color_(quantize_rgba8(color)), depth_(depth) {}
    uint64_t draw_tile(int, const Rect& r, const Target& t) override {
        Framebuffer& fb = *t.fb;
        const size_t n = size_t(r.x1 - r.x0) * size_t(fb.samples());
        static_assert(sizeof(Rgba8) == sizeof(uint32_t));
        uint32_t color;  // filled as 32-bit words, which vectorizes (four bytes do not)
        std::memcpy(&color, &color_, sizeof color);
        // The tile's rows are far apart in memory, out of reach of the hardware prefetcher:
        // ask for the rows a few ahead, or each row's writes wait for memory one after
        // another (bench/micro BM_ClearTiles: 1.9 -> 1.3 ms at 1080p).
        constexpr int kAhead = 4;
        for (int y = r.y0; y < r.y1; ++y) {
            if (y + kAhead < r.y1) {
                const auto* c = reinterpret_cast<const char*>(fb.color_data() + fb.sample_index(r.x0, y + kAhead));
                const auto* d = reinterpret_cast<const char*>(fb.depth_data() + fb.sample_index(r.x0, y + kAhead));
                for (size_t k = 0; k < n * sizeof(float); k += 64) {
                    __builtin_prefetch(c + k, /*write=*/1);
                    __builtin_prefetch(d + k, /*write=*/1);
                }
            }
            std::fill_n(reinterpret_cast<uint32_t*>(fb.color_data() + fb.sample_index(r.x0, y)), n, color);
            std::fill_n(fb.depth_data() + fb.sample_index(r.x0, y), n, depth_);
        }
        return 0;
    }

private:
    Rgba8 color_;
    float depth_;
};

inline constexpr size_t kVertexChunk = 16384;
inline constexpr size_t kTriangleChunk = 8192;

template <Shader S, int Samples, BlendMode B>
class TriangleCommand final : public Command {
public:
    static constexpr int N = kVaryingCount<typename S::Varyings>;
    using Vertex = typename S::Vertex;

    TriangleCommand(const S& shader, const RenderState& state, std::span<const Vertex> vertices, std::span<const uint32_t> indices)
        : shader_(shader), state_(state), vertices_(vertices), indices_(indices) {
        allows_hsr_ = PureShader<S> && B == BlendMode::Opaque && softraster::allows_hidden_surface_removal(state_);
    }

    size_t vertex_chunks() const override { return (vertices_.size() + kVertexChunk - 1) / kVertexChunk; }
    void process_vertex_chunk(size_t c, const Target& t) override {
        if (SOFTRASTER_HAS_AVX2_PATH && simd::cpu_has_avx2()) process_vertex_chunk_avx2(c, t);
        else process_vertex_chunk_generic(c, t);
    }
    void prepare() override {
        post_.resize(vertices_.size());
        bins_.resize(primitive_chunks());
    }

    size_t primitive_chunks() const override { return (indices_.size() / 3 + kTriangleChunk - 1) / kTriangleChunk; }
    void bin_primitive_chunk(size_t c, const Target& t) override {
        if (SOFTRASTER_HAS_AVX2_PATH && simd::cpu_has_avx2()) bin_primitive_chunk_avx2(c, t);
        else bin_primitive_chunk_generic(c, t);
    }

    uint64_t draw_tile(int tile, const Rect& rect, const Target& t) override {
        if (SOFTRASTER_HAS_AVX2_PATH && simd::cpu_has_avx2()) return draw_tile_avx2(tile, rect, t);
        return draw_tile_generic(tile, rect, t);
    }

    void finish_binning(const TileGrid& grid) override {
        tile_triangles_.assign(size_t(grid.count()), 0);
        tile_area_.assign(size_t(grid.count()), 0.0);
        for (const TriangleBin<N>& bin : bins_)
            for (size_t tile = 0; tile < tile_triangles_.size(); ++tile) {
                tile_triangles_[tile] += bin.tile_begin[tile + 1] - bin.tile_begin[tile];
                tile_area_[tile] += bin.covered_area[tile];
            }
    }
    void visibility_pass(int tile, const Rect& rect, const Target& t, uint32_t draw, uint32_t* owners) override {
        if (SOFTRASTER_HAS_AVX2_PATH && simd::cpu_has_avx2()) visibility_avx2(tile, rect, t, draw, owners);
        else visibility_generic(tile, rect, t, draw, owners);
    }
    uint64_t shading_pass(int tile, const Rect& rect, const Target& t, uint32_t draw, const uint32_t* owners) override {
        if (SOFTRASTER_HAS_AVX2_PATH && simd::cpu_has_avx2()) return shading_avx2(tile, rect, t, draw, owners);
        return shading_generic(tile, rect, t, draw, owners);
    }

private:
    SOFTRASTER_AVX2_TARGET void visibility_avx2(int tile, const Rect& rect, const Target& t, uint32_t draw, uint32_t* owners) {
        visibility_body(tile, rect, t, draw, owners);
    }
    SOFTRASTER_FLATTEN void visibility_generic(int tile, const Rect& rect, const Target& t, uint32_t draw, uint32_t* owners) {
        visibility_body(tile, rect, t, draw, owners);
    }
    SOFTRASTER_AVX2_TARGET uint64_t shading_avx2(int tile, const Rect& rect, const Target& t, uint32_t draw, const uint32_t* owners) {
        return shading_body(tile, rect, t, draw, owners);
    }
    SOFTRASTER_FLATTEN uint64_t shading_generic(int tile, const Rect& rect, const Target& t, uint32_t draw, const uint32_t* owners) {
        return shading_body(tile, rect, t, draw, owners);
    }

    // The front end, like the back end, twice: for any x86-64 and with AVX2 (same bits).
    SOFTRASTER_AVX2_TARGET void process_vertex_chunk_avx2(size_t c, const Target& t) { process_vertex_chunk_body(c, t); }
    SOFTRASTER_FLATTEN void process_vertex_chunk_generic(size_t c, const Target& t) { process_vertex_chunk_body(c, t); }
    void process_vertex_chunk_body(size_t c, const Target& t) {
        const size_t begin = c * kVertexChunk, end = std::min(vertices_.size(), begin + kVertexChunk);
        process_vertices(shader_, vertices_, begin, end, t.planes, t.viewport, std::span<ShadedVertex<N>>(post_));
    }
    SOFTRASTER_AVX2_TARGET void bin_primitive_chunk_avx2(size_t c, const Target& t) { bin_primitive_chunk_body(c, t); }
    SOFTRASTER_FLATTEN void bin_primitive_chunk_generic(size_t c, const Target& t) { bin_primitive_chunk_body(c, t); }
    void bin_primitive_chunk_body(size_t c, const Target& t) {
        const size_t tris = indices_.size() / 3, begin = c * kTriangleChunk, end = std::min(tris, begin + kTriangleChunk);
        bin_triangles<Samples>(indices_.subspan(begin * 3, (end - begin) * 3), post_.data(), t.planes, t.viewport,
                      FaceState{state_.cull, state_.front_face}, t.grid, bins_[c]);
    }

    // Pass 1: depth test and write, and the owner of every sample that passes.
    void visibility_body(int tile, const Rect& rect, const Target& t, uint32_t draw, uint32_t* owners) {
        Framebuffer& fb = *t.fb;
        const int width = fb.width();
        for_each_setup(tile, rect, [&](const TriangleSetup<N>& setup, uint32_t id) {
            const uint32_t me = owner_id(draw, id);
            if constexpr (Samples == 1) {  // eight pixels at a time
                using namespace simd;
                rasterize_spans(setup, setup.bounds, [&](int y, int x_begin, int x_end) {
                    float* depth = fb.depth_data() + fb.sample_index(0, y);
                    int32_t* owner = reinterpret_cast<int32_t*>(owners) + size_t(y - rect.y0) * kTileSize;  // by x - rect.x0
                    const f8 j = splat(float(y - setup.origin_y));
                    for_each_group(x_begin, x_end, [&](int x, i8 pass) {
                        const f8 z = interpolate_depth(setup, to_float(kLaneIndex) + float(x - setup.origin_x), j);
                        const f8 stored = load_group<f8>(depth, x, width);
                        pass &= depth_passes(state_.depth_func, z, stored);
                        store_group(depth, x, width, select(pass, z, stored));
                        const int ox = x - rect.x0, ow = width - rect.x0;
                        store_group(owner, ox, ow, select(pass, splat_i(int32_t(me)), load_group<i8>(owner, ox, ow)));
                    });
                });
                return;
            }
            rasterize_triangle<Samples>(setup, setup.bounds, [&](const CoveredPixel<Samples>& px) {
                float* depth = fb.depth_data() + fb.sample_index(px.x, px.y);
                uint32_t* owner = owners + (size_t(px.y - rect.y0) * kTileSize + size_t(px.x - rect.x0)) * Samples;
                for (int s = 0; s < Samples; ++s)
                    if ((px.mask & (1u << s)) && depth_passes(state_.depth_func, px.z[size_t(s)], depth[s])) {
                        depth[s] = px.z[size_t(s)];
                        owner[s] = me;
                    }
            });
        });
    }

    // Pass 2: shade each pixel for the triangle that owns some of its samples.
    uint64_t shading_body(int tile, const Rect& rect, const Target& t, uint32_t draw, const uint32_t* owners) {
        using V = typename S::Varyings;
        Framebuffer& fb = *t.fb;
        const int width = fb.width();
        uint64_t shaded = 0;
        for_each_setup(tile, rect, [&](const TriangleSetup<N>& setup, uint32_t id) {
            const uint32_t me = owner_id(draw, id);
            if constexpr (Samples == 1 && BatchShader<S>) {  // eight pixels at a time
                using namespace simd;
                rasterize_spans(setup, setup.bounds, [&](int y, int x_begin, int x_end) {
                    const int32_t* owner = reinterpret_cast<const int32_t*>(owners) + size_t(y - rect.y0) * kTileSize;  // by x - rect.x0
                    Rgba8* color = fb.color_data() + fb.sample_index(0, y);
                    const f8 j = splat(float(y - setup.origin_y));
                    for_each_group(x_begin, x_end, [&](int x, i8 lanes) {
                        const i8 mine = lanes & (load_group<i8>(owner, x - rect.x0, width - rect.x0) == int32_t(me));
                        if (!any(mine)) return;
                        const f8 i = to_float(kLaneIndex) + float(x - setup.origin_x);
                        std::array<f8, 4> rgba;
                        shader_.fragment_batch(interpolate_perspective(setup, i, j), interpolate_depth(setup, i, j), setup.front_facing, rgba);
                        shaded += unsigned(__builtin_popcount(bits(mine)));
                        blend_group<BlendMode::Opaque>(color, x, width, mine, rgba);
                    });
                });
                return;
            }
            rasterize_triangle<Samples>(setup, setup.bounds, [&](const CoveredPixel<Samples>& px) {
                const uint32_t* owner = owners + (size_t(px.y - rect.y0) * kTileSize + size_t(px.x - rect.x0)) * Samples;
                unsigned mine = 0;
                for (int s = 0; s < Samples; ++s)
                    if ((px.mask & (1u << s)) && owner[s] == me) mine |= 1u << s;
                if (!mine) return;
                const float i = float(px.x - setup.origin_x), j = float(px.y - setup.origin_y);
                const V v = from_array<V>(interpolate_perspective(setup, i, j));
                glm::vec4 color;
                shader_.fragment(v, FragCoord{float(px.x) + 0.5f, float(px.y) + 0.5f, interpolate_depth(setup, i, j), setup.front_facing}, color);
                ++shaded;
                const Rgba8 c = quantize_rgba8(color);
                Rgba8* dst = fb.color_data() + fb.sample_index(px.x, px.y);
                for (int s = 0; s < Samples; ++s)
                    if (mine & (1u << s)) dst[s] = c;
            });
        });
        return shaded;
    }

    // Draws that shade through the fragment queue: opaque, with a shader that never discards.
    static constexpr bool kQueued = BatchShader<S> && PureShader<S> && B == BlendMode::Opaque;
    // A triangle at least this big in the tile is shaded directly, row group by row group.
    static bool is_large(const Rect& r) { return (r.x1 - r.x0) >= 32 && (r.y1 - r.y0) >= 16; }

    // The same code twice: once for any x86-64, once with AVX2 allowed, where eight-lane
    // vectors are one register. Everything it calls is inlined into each (flatten).
    SOFTRASTER_AVX2_TARGET uint64_t draw_tile_avx2(int tile, const Rect& rect, const Target& t) {
        return draw_tile_body</*wide_lanes=*/true>(tile, rect, t);
    }
    SOFTRASTER_FLATTEN uint64_t draw_tile_generic(int tile, const Rect& rect, const Target& t) {
        return draw_tile_body</*wide_lanes=*/false>(tile, rect, t);
    }
    // Eight pixels at a time where the shader can (single-sampled); without wide vector
    // registers only for triangles wide enough to fill the lanes.
    template <bool WideLanes>
    uint64_t draw_tile_body(int tile, const Rect& rect, const Target& t) {
        uint64_t shaded = 0;
        if constexpr (kQueued) {
            if (state_.color_write && triangles_in_tile(tile) > 0) {  // small triangles shaded in full groups of eight (fragment_queue.h)
                // One queue per thread, off the stack: a few kilobytes that would otherwise
                // sit among the tile loop's spilled registers.
                static thread_local FragmentQueue<S, Samples> queue;
                queue.start(shader_, *t.fb);
                for_each_setup</*planes=*/false>(tile, rect, [&](TriangleSetup<N>& setup, uint32_t) {
                    if (Samples == 1 && is_large(setup.bounds)) {  // its groups are full anyway
                        queue.flush();
                        setup_planes(setup);
                        shaded += draw_triangle_batched<B>(shader_, state_, *t.fb, setup);
                    } else {
                        shaded += queue_triangle<Samples>(state_, *t.fb, setup, queue);  // makes the planes if needed
                    }
                });
                queue.flush();
                return shaded;
            }
        }
        for_each_setup(tile, rect, [&](const TriangleSetup<N>& setup, uint32_t) {
            if constexpr (Samples == 1 && BatchShader<S>) {
                if (WideLanes || setup.bounds.x1 - setup.bounds.x0 >= 16) {
                    shaded += draw_triangle_batched<B>(shader_, state_, *t.fb, setup);
                    return;
                }
            }
            shaded += draw_triangle<Samples, B>(shader_, state_, *t.fb, setup);
        });
        return shaded;
    }

    // Calls f(setup, ordinal) for each of the tile's triangles in draw order; the ordinal
    // counts the tile's triangles of this draw (the owner id of hidden-surface removal).
    // Without Planes, the setup has its coverage only (f makes the planes when it needs them).
    template <bool Planes = true, class F>
    void for_each_setup(int tile, const Rect& rect, F&& f) const {
        TriangleSetup<N> setup;
        uint32_t ordinal = 0;
        // Setup reads the window position and varyings of three vertices anywhere in the
        // draw's vertex buffer: fetch those of a triangle a few places ahead into the cache
        // while this one is drawn, or the loads wait on memory (a tile revisits every draw).
        constexpr uint32_t kAhead = 4;
        auto prefetch = [&](const TriangleBin<N>& bin, const TriangleRef& r) {
            for (uint32_t i : r.v) {
                const ShadedVertex<N>& v = bin.vertex(i, post_.data());
                __builtin_prefetch(&v);  // at most two cache lines
                __builtin_prefetch(reinterpret_cast<const char*>(&v + 1) - 1);
            }
        };
        for (const TriangleBin<N>& bin : bins_)
            for (uint32_t k = bin.tile_begin[size_t(tile)], end = bin.tile_begin[size_t(tile) + 1]; k < end; ++k, ++ordinal) {
                if (k == bin.tile_begin[size_t(tile)])
                    for (uint32_t a = k + 1; a < std::min(end, k + kAhead); ++a) prefetch(bin, bin.refs[a]);
                if (k + kAhead < end) prefetch(bin, bin.refs[k + kAhead]);
                const TriangleRef& r = bin.refs[k];
                if (setup_coverage<Samples>(bin.vertex(r.v[0], post_.data()), bin.vertex(r.v[1], post_.data()),
                                   bin.vertex(r.v[2], post_.data()), state_.front_face, rect, setup)) {
                    if constexpr (Planes) setup_planes(setup);
                    f(setup, ordinal);
                }
            }
    }
    S shader_;
    RenderState state_;
    std::span<const Vertex> vertices_;
    std::span<const uint32_t> indices_;
    std::vector<ShadedVertex<N>> post_;
    std::vector<TriangleBin<N>> bins_;
};

// Lines and points: few and cheap, so the front end keeps them as one list (clipped and in
// window space) and every tile walks all of them, drawing only its own pixels.
template <Shader S, int Samples, BlendMode B>
class LinePointCommand final : public Command {
public:
    static constexpr int N = kVaryingCount<typename S::Varyings>;
    using Vertex = typename S::Vertex;

    LinePointCommand(Topology topology, const S& shader, const RenderState& state, std::span<const Vertex> vertices,
                     std::span<const uint32_t> indices)
        : topology_(topology), shader_(shader), state_(state), vertices_(vertices), indices_(indices) {}

    size_t primitive_chunks() const override { return 1; }
    void bin_primitive_chunk(size_t, const Target& t) override {
        std::vector<ShadedVertex<N>> post(vertices_.size());
        process_vertices(shader_, vertices_, 0, vertices_.size(), t.planes, t.viewport, std::span<ShadedVertex<N>>(post));
        window_.clear();
        const ClipPlanes frustum = ClipPlanes::frustum();
        const size_t per = topology_ == Topology::Lines ? 2 : 1;
        for (size_t i = 0; i + per <= indices_.size(); i += per) {
            ClipVertex<N> a = post[indices_[i]].clip, b = post[indices_[i + per - 1]].clip;
            if (!post[indices_[i]].finite || !post[indices_[i + per - 1]].finite) continue;
            if (per == 2 ? !clip_line(a, b, frustum) : frustum.outcode(a.position) != 0) continue;
            WindowVertex<N> wa, wb;
            if (!to_window(a, t.viewport, wa) || !to_window(b, t.viewport, wb)) continue;
            window_.push_back(wa);
            if (per == 2) window_.push_back(wb);
        }
    }

    uint64_t draw_tile(int, const Rect& rect, const Target& t) override {
        using V = typename S::Varyings;
        uint64_t shaded = 0;
        auto fragment = [&](int x, int y, float z, auto&& make_varyings) {
            std::array<float, Samples> zs;
            zs.fill(z);
            shade_fragment<Samples, B>(shader_, state_, *t.fb, x, y, (1u << Samples) - 1, zs.data(), z, true, make_varyings, shaded);
        };
        if (topology_ == Topology::Points) {
            for (const WindowVertex<N>& p : window_)
                rasterize_point(p, rect, [&](int x, int y, float z) { fragment(x, y, z, [&] { return from_array<V>(p.var); }); });
            return shaded;
        }
        for (size_t i = 0; i + 1 < window_.size(); i += 2) {
            const WindowVertex<N>&a = window_[i], &b = window_[i + 1];
            rasterize_line(a, b, rect, [&](int x, int y, float z, float s) {
                fragment(x, y, z, [&] {
                    std::array<float, N> v;
                    for (size_t k = 0; k < size_t(N); ++k) v[k] = a.var[k] + s * (b.var[k] - a.var[k]);
                    return from_array<V>(v);
                });
            });
        }
        return shaded;
    }

private:
    Topology topology_;
    S shader_;
    RenderState state_;
    std::span<const Vertex> vertices_;
    std::span<const uint32_t> indices_;
    std::vector<WindowVertex<N>> window_;
};

}  // namespace softraster
