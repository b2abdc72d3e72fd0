// The recorded commands a Context executes: a clear, and draws of triangles, lines and
// points. Each runs in three phases, every phase over all commands in parallel:
//   1. vertex processing (vertex_processing.h), in chunks of vertices;
//   2. primitive assembly, clipping, culling and binning (binning.h, bin_triangles), in
//      chunks of primitives (a draw of one chunk of each does 1 and 2 as one item, see
//      Context::execute); lines and points become two triangles each on the way
//      (line_point_quads.h), so from here on every draw is of triangles;
//   3. per tile, in draw order, the tile back end (tile_back_end.h): triangle setup,
//      rasterization, depth test, fragment shading, output merge.
// A command is a type-erased draw: one virtual call per chunk or per tile. Vertex processing
// is specialized for the shader; everything per pixel for the shader's varying layout
// (shader_layout.h) and the sample count, with the shader's fragment code called out of
// line a batch at a time (whether the draw blends is a per-draw value, tile_back_end.h). Each phase runs in the copy for this
// CPU (simd.h, on_best_path).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/general_back_end.h"
#include "softraster/pipeline/hidden_surface_removal.h"
#include "softraster/pipeline/line_point_quads.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/pipeline/tile_back_end.h"
#include "softraster/pipeline/vertex_processing.h"

namespace softraster {

// Where commands draw during one execution.
struct DrawTarget {
    Framebuffer* fb = nullptr;
    TileGrid grid;
    ClipPlanes planes;  // with the guard band for this viewport
    Viewport viewport;
};

// On cache lines of its own (alignas): the front ends of two draws side by side in memory
// may run on two threads, each writing its command, and a line the two shared went from
// core to core (docs/performance.md, "Commands on lines of their own").
class alignas(kCacheLine) Command {
public:
    virtual ~Command() = default;
    // Bytes of post-transform vertices its front end writes for its back end to read.
    virtual size_t post_transform_bytes() const { return 0; }
    // Places those vertices at `memory` (post_transform_bytes() of it, 64-byte aligned: the
    // context's, reused batch after batch) and sizes the command's other buffers: before
    // the parallel phases, or for a small draw first thing on the thread that takes it.
    virtual void prepare(std::byte* /*memory*/) {}
    virtual size_t vertex_chunks() const { return 0; }
    virtual void process_vertex_chunk(size_t, const DrawTarget&) {}
    virtual size_t primitive_chunks() const { return 0; }
    // (Binning writes the chunk's triangles per tile into `memory`, the thread's for the
    // batch: BinMemory.)
    virtual void bin_primitive_chunk(size_t, const DrawTarget&, BinMemory& /*memory*/) {}
    // A small draw (one chunk of vertices, one of primitives at most) goes through the front
    // end in one call on one thread: its primitives are binned right after its vertices are
    // processed, while they are still in this core's cache.
    bool small() const { return vertex_chunks() <= 1 && primitive_chunks() <= 1; }
    virtual void process_small(const DrawTarget&, BinMemory& /*memory*/) {}
    // After all its chunks are binned (a small draw's right after process_small, on the
    // same thread): the per-tile totals below.
    virtual void finish_binning(const TileGrid&) {}
    // Draws this command's part of one tile; returns the fragments shaded.
    virtual uint64_t draw_tile(int tile, const Rect& rect, const DrawTarget&) = 0;
    // A clear, which may leave its tile's samples unwritten (Framebuffer's deferred clears);
    // everything else draws on a settled tile.
    virtual bool is_clear() const { return false; }

    // Commands binned by tile draw only in the tiles their triangles touch; the others (a
    // clear) draw in every tile.
    bool binned() const { return binned_; }
    const TileRange& tiles() const { return range_; }
    size_t triangles_in_tile(int tile) const {
        const int k = local_tile(tile);
        if (k < 0) return 0;
        return one_bin_begin_ ? one_bin_begin_[k + 1] - one_bin_begin_[k] : tile_triangles_[size_t(k)];
    }
    // Bit k set where local tile k of tiles() has triangles (for a range of up to 64 tiles:
    // a small draw's footprint, Context::footprint_of).
    uint64_t tiles_with_triangles() const {
        uint64_t bits = 0;
        for (int k = 0, n = std::min(range_.count(), 64); k < n; ++k)
            if (one_bin_begin_ ? one_bin_begin_[k + 1] > one_bin_begin_[k] : tile_triangles_[size_t(k)] > 0) bits |= uint64_t(1) << k;
        return bits;
    }
    // Pixels of the tile this command's triangles cover, summed (each triangle's area, at
    // most its bounds within the tile): an estimate of the overdraw.
    double covered_area(int tile) const {
        const int k = local_tile(tile);
        if (k < 0) return 0.0;
        return one_bin_area_ ? double(one_bin_area_[k]) : tile_area_[size_t(k)];
    }

    // Whether the command tests stencil (the framebuffer then needs a stencil buffer).
    virtual bool uses_stencil() const { return false; }

    // Hidden-surface removal (hidden_surface_removal.h), for commands that allow it.
    bool allows_hidden_surface_removal() const { return allows_hsr_; }
    virtual void visibility_pass(int, const Rect&, const DrawTarget&, uint32_t /*draw*/, uint32_t* /*owners*/) {}
    virtual uint64_t shading_pass(int, const Rect&, const DrawTarget&, uint32_t /*draw*/, const uint32_t* /*owners*/) { return 0; }

protected:
    // The part of a tile's rectangle the draw may touch: all of it, or its cut with the scissor.
    static Rect scissored(const Rect& rect, const RenderState& st) {
        if (!st.scissor_test) return rect;
        const ScissorRect& s = st.scissor;
        return intersect(rect, Rect{s.x, s.y, s.x + s.width, s.y + s.height});
    }

    // The per-tile totals of a command binned in `bins`, over the tiles any chunk touches.
    template <int N>
    void sum_bins(std::span<const TriangleBin<N>> bins, const TileGrid& grid) {
        binned_ = true;
        grid_ = grid;
        // One chunk (every draw of up to kTriangleChunk triangles): its own per-tile lists
        // are the totals, read in place instead of copied into two more allocations per draw.
        if (bins.size() == 1) {
            range_ = bins[0].range;
            one_bin_begin_ = bins[0].tile_begin.data();
            one_bin_area_ = bins[0].covered_area.data();
            return;
        }
        one_bin_begin_ = nullptr;
        one_bin_area_ = nullptr;
        TileBounds all;
        for (const TriangleBin<N>& bin : bins)
            if (bin.range.count() > 0) all.include(bin.range.x0, bin.range.y0, bin.range.x1 - 1, bin.range.y1 - 1);
        range_ = all.range();
        tile_triangles_.assign(size_t(range_.count()), 0);
        tile_area_.assign(size_t(range_.count()), 0.0);
        for (const TriangleBin<N>& bin : bins)
            for (int ty = bin.range.y0; ty < bin.range.y1; ++ty)
                for (int tx = bin.range.x0; tx < bin.range.x1; ++tx) {
                    const auto k = size_t(range_.local(tx, ty)), b = size_t(bin.range.local(tx, ty));
                    tile_triangles_[k] += bin.tile_begin[b + 1] - bin.tile_begin[b];
                    tile_area_[k] += bin.covered_area[b];
                }
    }
    int local_tile(int tile) const { return binned_ ? range_.local(grid_.tile_x(tile), grid_.tile_y(tile)) : -1; }

    bool allows_hsr_ = false;

private:
    bool binned_ = false;
    TileGrid grid_;  // the grid binned for
    TileRange range_;
    std::vector<uint32_t> tile_triangles_;  // per tile of range_
    std::vector<double> tile_area_;
    const uint32_t* one_bin_begin_ = nullptr;  // or a single bin's tile_begin and covered_area
    const float* one_bin_area_ = nullptr;
};

class ClearCommand final : public Command {
public:
    ClearCommand(const glm::vec4& color, float depth, uint8_t stencil = 0) : color_(color), depth_(depth), stencil_(stencil) {}
    // Depth only: a depth pass's clear (shadow maps) leaves the color it never reads alone.
    explicit ClearCommand(float depth) : depth_(depth), depth_only_(true) {}
    // Deferred where the context allows it (Framebuffer's deferred clears).
    uint64_t draw_tile(int tile, const Rect&, const DrawTarget& target) override {
        Framebuffer& fb = *target.fb;
        if (depth_only_) fb.clear_tile_depth(tile, depth_);
        else fb.clear_tile(tile, quantize_rgba8(color_, fb.color_space()), depth_, stencil_);  // (as glClear with GL_FRAMEBUFFER_SRGB)
        return 0;
    }
    bool is_clear() const override { return true; }

private:
    glm::vec4 color_{0.0f};
    float depth_;
    uint8_t stencil_ = 0;
    bool depth_only_ = false;
};

inline constexpr size_t kVertexChunk = 16384;
inline constexpr size_t kTriangleChunk = 8192;

// Each phase's entry into the CPU dispatch, as a template of what it depends on only: the
// vertex phase is compiled once per shader, binning once per varying count (the sample
// pattern's extent a value), the back ends once per varying layout, whatever the blend mode or the other
// shaders of the same varyings.
namespace phases {
template <Shader S>
void process_vertices(const S& shader, std::span<const typename S::Vertex> vertices, size_t begin, size_t end,
                      const DrawTarget& target, std::span<ShadedVertex<kVaryingCount<typename S::Varyings>>> out, std::span<ClipInfo> clip) {
    simd::on_best_path([&]<bool WideLanes>() {
        softraster::process_vertices<WideLanes>(shader, vertices, begin, end, target.planes, target.viewport, out, clip);
    });
}
template <int N>
void bin_triangles(std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipInfo* clip, const DrawTarget& target,
                   const SampleExtent& samples, FaceState faces, FlatVaryings flat, TriangleBin<N>& bin, BinMemory& memory) {
    simd::on_best_path([&]<bool WideLanes>() {
        softraster::bin_triangles<WideLanes>(indices, post, clip, target.planes, target.viewport, samples, faces, flat, target.grid, bin, memory);
    });
}
template <int Samples, int N>
void visibility_pass(const BinnedTriangles<N>& triangles, const RenderState& state, Framebuffer& fb, int tx, int ty,
                     const Rect& rect, uint32_t draw, uint32_t* owners) {
    simd::on_best_path([&]<bool WideLanes>() {
        softraster::visibility_pass<Samples, WideLanes>(triangles, state, fb, tx, ty, rect, draw, owners);
    });
}
// The tile back end and the shading pass once per back end, whatever the topology the
// command was drawn with (lines and points draw the triangles of their quads).
template <class BackEnd>
uint64_t draw_tile(const BackEnd& back_end, int tx, int ty, const Rect& rect) {
    return simd::on_best_path([&]<bool WideLanes>() { return back_end.template draw<WideLanes>(tx, ty, rect); });
}
template <int Samples, class L>
uint64_t shading_pass(const LayoutShader<L>& shader, const BinnedTriangles<L::N>& triangles, const RenderState& state, Framebuffer& fb,
                      int tx, int ty, const Rect& rect, uint32_t draw, const uint32_t* owners) {
    return simd::on_best_path([&]<bool WideLanes>() {
        return softraster::shading_pass<Samples, L, WideLanes>(shader, triangles, state, fb, tx, ty, rect, draw, owners);
    });
}
template <class L>
uint64_t draw_tile_general(const LayoutShader<L>& shader, const FragmentOps& ops, const RenderState& state, const BinnedTriangles<L::N>& triangles,
                           Framebuffer& fb, int tx, int ty, const Rect& rect) {
    return softraster::draw_tile_general(shader, ops, state, triangles, fb, tx, ty, rect);
}
}  // namespace phases

// The clip parts of the small draw the calling thread is processing (process_small below):
// one buffer for every draw and every shader, reused draw after draw and so mostly in the
// core's cache, on lines no other thread writes (cache_line_allocator.h).
inline std::vector<ClipInfo, CacheLineAllocator<ClipInfo>>& small_draw_clip_parts() {
    static thread_local std::vector<ClipInfo, CacheLineAllocator<ClipInfo>> clip;
    return clip;
}

// The front end of a draw, the same for both back ends: vertex processing and binning in
// chunks (binned for the extent of the framebuffer's sample pattern), then the draw's triangles
// per tile. Of lines or points (T), the triangles of their quads (line_point_quads.h).
template <Shader S, Topology T>
class TriangleFrontEnd : public Command {
public:
    static constexpr int N = kVaryingCount<typename S::Varyings>;
    static constexpr size_t kPer = T == Topology::Triangles ? 3 : T == Topology::Lines ? 2 : 1;  // indices per primitive
    using Vertex = typename S::Vertex;

    TriangleFrontEnd(const S& shader, const RenderState& state, std::span<const Vertex> vertices, std::span<const uint32_t> indices)
        : shader_(shader), state_(state), vertices_(vertices), indices_(indices) {
        if constexpr (T != Topology::Triangles) {  // lines and points face front, no polygon offset
            state_.cull = CullMode::None;
            state_.polygon_offset_factor = state_.polygon_offset_units = 0.0f;
        }
    }

    bool uses_stencil() const override { return state_.stencil_test; }
    size_t post_transform_bytes() const override { return vertices_.size() * sizeof(ShadedVertex<N>); }
    void prepare(std::byte* memory) override {
        // (Not zeroed: vertex processing writes every vertex, and a vertex it cannot map to
        // the window is read only through its clip part.)
        post_ = {reinterpret_cast<ShadedVertex<N>*>(memory), vertices_.size()};
        if (!this->small()) clip_.resize(vertices_.size());  // (a small draw's: process_small)
        if (primitive_chunks() > 1) bins_.resize(primitive_chunks());  // (one: one_bin_)
    }
    size_t vertex_chunks() const override { return (vertices_.size() + kVertexChunk - 1) / kVertexChunk; }
    void process_vertex_chunk(size_t c, const DrawTarget& target) override {
        const size_t begin = c * kVertexChunk, end = std::min(vertices_.size(), begin + kVertexChunk);
        phases::process_vertices(shader_, vertices_, begin, end, target, post_, std::span<ClipInfo>(clip_));
    }
    // A small draw's clip parts are read by its binning alone, right after: they live in a
    // buffer of the thread's (small_draw_clip_parts), not in the draw's memory.
    void process_small(const DrawTarget& target, BinMemory& memory) override {
        auto& clip = small_draw_clip_parts();
        clip.resize(vertices_.size());
        if (vertex_chunks() == 1) phases::process_vertices(shader_, vertices_, 0, vertices_.size(), target, post_, std::span<ClipInfo>(clip));
        if (primitive_chunks() == 1) bin_chunk(0, target, clip.data(), memory);
    }
    size_t primitive_chunks() const override { return (indices_.size() / kPer + kTriangleChunk - 1) / kTriangleChunk; }
    void bin_primitive_chunk(size_t c, const DrawTarget& target, BinMemory& memory) override { bin_chunk(c, target, clip_.data(), memory); }
    void finish_binning(const TileGrid& grid) override { sum_bins<N>(bins(), grid); }

protected:
    // Bins chunk c of the primitives, whose corners' clip parts are `clip`, into `memory`.
    void bin_chunk(size_t c, const DrawTarget& target, const ClipInfo* clip, BinMemory& memory) {
        const size_t count = indices_.size() / kPer, begin = c * kTriangleChunk, end = std::min(count, begin + kTriangleChunk);
        const std::span<const uint32_t> chunk = indices_.subspan(begin * kPer, (end - begin) * kPer);
        const FlatVaryings flat{kFlatVaryings<S>, state_.provoking_vertex == ProvokingVertex::First};
        // The framebuffer's own pattern bounds the pixels a triangle may cover, whichever
        // back end draws it: a wider one would only hand the back end triangles that cover
        // none of its samples.
        const SampleExtent extent = with_sample_count(target.fb->samples(), []<int Samples>() { return sample_extent<Samples>(); });
        if constexpr (T == Topology::Triangles) {
            phases::bin_triangles(chunk, post_.data(), clip, target, extent, FaceState{state_.cull, state_.front_face}, flat, bin(c), memory);
        } else {
            const LinePointShape shape{state_.line_width, state_.point_size, target.fb->samples() > 1, state_.front_face};
            bin_lines_points(T, chunk, post_.data(), clip, target.planes, target.viewport, extent, shape, flat, target.grid, bin(c), memory);
        }
    }
    BinnedTriangles<N> triangles() const { return {bins(), post_.data()}; }
    // The chunks' bins: a draw of one chunk (most draws: up to kTriangleChunk triangles)
    // keeps its bin inline, an allocation fewer per draw.
    TriangleBin<N>& bin(size_t c) { return bins_.empty() ? one_bin_ : bins_[c]; }
    std::span<const TriangleBin<N>> bins() const {
        if (!bins_.empty()) return bins_;
        return {&one_bin_, primitive_chunks() == 1 ? size_t(1) : size_t(0)};
    }

    S shader_;
    RenderState state_;
    std::span<const Vertex> vertices_;
    std::span<const uint32_t> indices_;
    std::span<ShadedVertex<N>> post_;  // in the context's memory for the batch (prepare)
    std::vector<ClipInfo> clip_;  // the clip parts of a draw that is not small (a small one's: process_small)
    std::vector<TriangleBin<N>> bins_;  // two chunks or more
    TriangleBin<N> one_bin_;
};

template <Shader S, int Samples, Topology T = Topology::Triangles>
class TriangleCommand final : public TriangleFrontEnd<S, T> {
    using Base = TriangleFrontEnd<S, T>;
    using Base::shader_, Base::state_, Base::triangles;
    using L = LayoutOf<S>;

public:
    TriangleCommand(const S& shader, const RenderState& state, std::span<const typename S::Vertex> vertices,
                    std::span<const uint32_t> indices)
        : Base(shader, state, vertices, indices), layout_(layout_shader(shader_)) {
        this->allows_hsr_ = L::kPure && softraster::allows_hidden_surface_removal(state_);  // (opaque draws only)
    }

    uint64_t draw_tile(int tile, const Rect& tile_rect, const DrawTarget& target) override {
        const Rect rect = this->scissored(tile_rect, state_);
        if (rect.empty()) return 0;
        // A draw that writes no color (a shadow map's, an ambient occlusion pass's) with a
        // shader that never discards tests and writes depth alone: hidden-surface removal's
        // first pass without owners, from each triangle's edges and depth plane, with no
        // varyings and no shader.
        if (L::kPure && (!state_.color_write || state_.color_mask == 0)) {
            phases::visibility_pass<Samples>(triangles(), state_, *target.fb, target.grid.tile_x(tile), target.grid.tile_y(tile), rect, 0, nullptr);
            return 0;
        }
        const TileBackEnd<L, Samples> back_end{layout_, state_, DepthStencilTest(DepthTest(state_)), BlendSettings(state_, target.fb->color_space()),
                                                         triangles(), *target.fb};
        return phases::draw_tile(back_end, target.grid.tile_x(tile), target.grid.tile_y(tile), rect);
    }

    void visibility_pass(int tile, const Rect& rect, const DrawTarget& target, uint32_t draw, uint32_t* owners) override {
        if constexpr (L::kPure)
            phases::visibility_pass<Samples>(triangles(), state_, *target.fb, target.grid.tile_x(tile),
                                             target.grid.tile_y(tile), rect, draw, owners);
    }
    uint64_t shading_pass(int tile, const Rect& rect, const DrawTarget& target, uint32_t draw, const uint32_t* owners) override {
        if constexpr (L::kPure)
            return phases::shading_pass<Samples>(layout_, triangles(), state_, *target.fb, target.grid.tile_x(tile),
                                                 target.grid.tile_y(tile), rect, draw, owners);
        return 0;
    }

private:
    LayoutShader<L> layout_;  // shader_ as the back ends call it
};

// A triangle draw in the general back end (general_back_end.h): the same front end, then
// one fragment at a time with every per-fragment operation. Compiled once per varying layout.
template <Shader S, Topology T = Topology::Triangles>
class GeneralTriangleCommand final : public TriangleFrontEnd<S, T> {
    // One command type serves every sample count: the back end takes the count as a value,
    // and binning the pattern's extent (TriangleFrontEnd::bin_primitive_chunk).
    using Base = TriangleFrontEnd<S, T>;
    using Base::shader_, Base::state_, Base::triangles;
    using L = LayoutOf<S>;

public:
    GeneralTriangleCommand(const S& shader, const RenderState& state, int samples, ColorSpace color,
                           std::span<const typename S::Vertex> vertices, std::span<const uint32_t> indices)
        : Base(shader, state, vertices, indices), ops_(state, samples, !L::kPure, color), layout_(layout_shader(shader_)) {}

    uint64_t draw_tile(int tile, const Rect& tile_rect, const DrawTarget& target) override {
        const Rect rect = this->scissored(tile_rect, state_);
        if (rect.empty()) return 0;
        const int tx = target.grid.tile_x(tile), ty = target.grid.tile_y(tile);
        if constexpr (L::kBatch) {
            // Single-sampled and opaque (or writing no color), with nothing after the shader
            // that could drop a fragment: the fast back end (its fragment queue for small
            // triangles, groups of eight for big ones), with the stencil test where it tests
            // depth. Blended stencil draws and partial color masks, rare state, stay pixel by
            // pixel below.
            if (ops_.samples == 1 && ops_.early && (ops_.blend.replace || !ops_.blend.color_mask)) {
                const TileBackEnd<L, 1> back_end{layout_, state_, ops_.tests, ops_.blend, triangles(), *target.fb};
                return phases::draw_tile(back_end, tx, ty, rect);
            }
        }
        return phases::draw_tile_general(layout_, ops_, state_, triangles(), *target.fb, tx, ty, rect);
    }

private:
    FragmentOps ops_;
    LayoutShader<L> layout_;
};

}  // namespace softraster
