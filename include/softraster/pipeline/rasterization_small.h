// Stage 8, rasterization, eight pixels at a time: for small triangles, coverage in 32-bit
// integer lanes (Giesen, "Optimizing the basic rasterizer", 2013; llvmpipe does the same
// with 32-bit steps inside a 64x64 tile); for any triangle, from each row's exact spans
// (rasterize_span_groups, at the end).
//
// The edge functions of rasterization.h need 64 bits for a triangle anywhere in the guard
// band. A triangle whose edges each span at most kSmallEdge (64 pixels) in x and in y needs
// far fewer: at a point p the rasterizer visits (within the triangle's pixel bounds, or at most
// eight pixels beyond them in an aligned group), E(p) = A (p.x - a.x) + B (p.y - a.y) with
// |A|, |B| <= 2^14 and |p - a| < 2^14 + 2^12 per axis, so |E| < 2^30: it fits in an int32
// lane. Each row is then a few vector additions per group of eight pixels, with no span
// search and no per-pixel loop; most triangles of a detailed mesh are this small.
#pragma once
#include <array>
#include <cstdint>
#include <cstdlib>

#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

inline constexpr int64_t kSmallEdge = int64_t(64) * kSubpixelOne;
inline constexpr int32_t kSubpixelOne32 = int32_t(kSubpixelOne);

inline bool has_small_edges(const TriangleEdges& t) {
    for (size_t i = 0; i < 3; ++i)
        if (std::llabs(t.A[i]) > kSmallEdge || std::llabs(t.B[i]) > kSmallEdge) return false;
    return true;
}

// Edge i's value plus its fill-rule bias at the center of pixel (x, y), where the argument
// above puts it in 32 bits: the start of a small triangle's lanes.
inline int32_t edge_at_center32(const TriangleEdges& t, size_t i, int x, int y) {
    return int32_t(t.edge(int(i), int64_t(x) * kSubpixelOne32 + 128, int64_t(y) * kSubpixelOne32 + 128) + t.bias[i]);
}

// Per-lane offsets, in 1/256 pixel from the center of a group's first pixel, of the points a
// group covers: one sample per pixel, eight pixels; or with 4x MSAA four vectors in the
// framebuffer's order (vector v: pixels 2v and 2v + 1, samples 0-3 of each).
template <int Samples>
struct GroupSamples;
template <>
struct GroupSamples<1> {
    static constexpr int kVectors = 1;
    static simd::i8 dx(int) { return simd::kLaneIndex * kSubpixelOne32; }
    static simd::i8 dy(int) { return simd::i8{}; }
    static simd::i8 pixel(int) { return simd::kLaneIndex; }
};
template <>
struct GroupSamples<4> {
    static constexpr int kVectors = 4;
    static simd::i8 pixel(int v) { return 2 * v + (simd::kLaneIndex >> 2); }
    static simd::i8 dx(int v) {
        using P = SamplePattern<4>;
        return pixel(v) * kSubpixelOne32 + simd::i8{P::x[0], P::x[1], P::x[2], P::x[3], P::x[0], P::x[1], P::x[2], P::x[3]} - 128;
    }
    static simd::i8 dy(int) {
        using P = SamplePattern<4>;
        return simd::i8{P::y[0], P::y[1], P::y[2], P::y[3], P::y[0], P::y[1], P::y[2], P::y[3]} - 128;
    }
};

// Calls on_group(y, x, covered) for each group of eight pixels [x, x + 8) (x a multiple of
// eight) in a row of t.bounds that covers any sample, `covered` holding a lane mask per
// vector of GroupSamples<Samples>. Needs has_small_edges(t).
template <int Samples, class OnGroup>
void rasterize_small(const TriangleEdges& t, OnGroup&& on_group) {
    using namespace simd;
    using G = GroupSamples<Samples>;
    constexpr int V = G::kVectors;
    const Rect& r = t.bounds;
    const int gx0 = r.x0 & ~(kLanes - 1);
    // E + bias at each lane's point of the first group of the first row, and its steps
    std::array<std::array<i8, 3>, V> row;
    std::array<int32_t, 3> step_x, step_y;
    for (size_t i = 0; i < 3; ++i) {
        const int32_t e = edge_at_center32(t, i, gx0, r.y0);
        const auto a = int32_t(t.A[i]), b = int32_t(t.B[i]);
        for (int v = 0; v < V; ++v) row[size_t(v)][i] = e + a * G::dx(v) + b * G::dy(v);
        step_x[i] = a * kSubpixelOne32 * kLanes;
        step_y[i] = b * kSubpixelOne32;
    }
    std::array<i8, V> in_x;  // lanes whose pixel lies in [r.x0, r.x1), for the current group
    std::array<i8, V> covered;
    for (int y = r.y0; y < r.y1; ++y) {
        std::array<std::array<i8, 3>, V> e = row;
        for (int x = gx0; x < r.x1; x += kLanes) {
            i8 any_lane{};
            for (size_t v = 0; v < size_t(V); ++v) {
                const i8 px = G::pixel(int(v)) + x;
                in_x[v] = (px >= r.x0) & (px < r.x1);
                covered[v] = in_x[v] & ((e[v][0] | e[v][1] | e[v][2]) >= 0);
                any_lane |= covered[v];
                for (size_t i = 0; i < 3; ++i) e[v][i] += step_x[i];
            }
            if (any(any_lane)) on_group(y, x, covered);
        }
        for (auto& rv : row)
            for (size_t i = 0; i < 3; ++i) rv[i] += step_y[i];
    }
}

// Single-sampled, for a triangle at most four pixels wide: blocks of four columns by two
// rows, a block a vector (lane l: column l % 4, row l / 4). A triangle of a few pixels then
// costs one or two coverage tests, depth tests and queued groups, where a row at a time
// costs one per row, each with a lane or two in use. Calls on_block(x, y, covered) for each
// block [x, x + 4) x [y, y + 2) that covers a pixel center, from (x, y) down past the bounds'
// last row. (x, y) is the caller's to choose: at most three columns left of the bounds and
// one row above them, so that the 32-bit argument above holds. Needs has_small_edges(t).
inline constexpr int kBlockColumns = 4, kBlockRows = 2;
inline const simd::i8 kBlockColumn = {0, 1, 2, 3, 0, 1, 2, 3}, kBlockRow = {0, 0, 0, 0, 1, 1, 1, 1};

template <class OnBlock>
void rasterize_blocks(const TriangleEdges& t, int x, int y, OnBlock&& on_block) {
    using namespace simd;
    const Rect& r = t.bounds;
    const i8 px = kBlockColumn + x;
    const i8 in_x = (px >= r.x0) & (px < r.x1);
    std::array<i8, 3> e;
    std::array<int32_t, 3> step_y;
    for (size_t i = 0; i < 3; ++i) {
        const auto a = int32_t(t.A[i]), b = int32_t(t.B[i]);
        e[i] = edge_at_center32(t, i, x, y) + a * kSubpixelOne32 * kBlockColumn + b * kSubpixelOne32 * kBlockRow;
        step_y[i] = b * kSubpixelOne32 * kBlockRows;
    }
    for (; y < r.y1; y += kBlockRows) {
        const i8 py = kBlockRow + y;
        const i8 covered = in_x & (py >= r.y0) & (py < r.y1) & ((e[0] | e[1] | e[2]) >= 0);
        if (any(covered)) on_block(x, y, covered);
        for (size_t i = 0; i < 3; ++i) e[i] += step_y[i];
    }
}

// The same calls for a triangle of any size: each row's coverage from the exact span of
// pixels inside all three edges at each sample position (SampleRows, 64-bit, as
// rasterize_triangle finds them), turned into lane masks by comparing each lane's pixel with
// its sample's span. A big triangle's rows then cost three divisions per sample and a few
// vector operations per group, not a loop over its pixels and samples.
template <int Samples, class OnGroup>
void rasterize_span_groups(const TriangleEdges& t, OnGroup&& on_group) {
    using namespace simd;
    using G = GroupSamples<Samples>;
    constexpr int V = G::kVectors;
    const Rect& r = t.bounds;
    const int n = r.x1 - r.x0;
    if (n <= 0 || r.y0 >= r.y1) return;
    SampleRows<Samples> rows(t, r.x0, r.y0);
    const i8 lane_sample = kLaneIndex & (Samples - 1);  // (the lanes' samples, GroupSamples' order)
    for (int y = r.y0; y < r.y1; ++y) {
        std::array<int32_t, Samples> begin, end;  // sample s's span of pixels [begin, end)
        int lo = r.x1, hi = r.x0;
        for (size_t s = 0; s < size_t(Samples); ++s) {
            const Span sp = rows.span(s, n);
            begin[s] = r.x0 + sp.begin, end[s] = r.x0 + sp.end;
            if (sp.begin < sp.end) lo = std::min(lo, begin[s]), hi = std::max(hi, end[s]);
        }
        rows.next_row();
        if (lo >= hi) continue;
        i8 lane_begin, lane_end;
        for (int l = 0; l < kLanes; ++l) lane_begin[l] = begin[size_t(lane_sample[l])], lane_end[l] = end[size_t(lane_sample[l])];
        std::array<i8, V> covered;
        for (int x = lo & ~(kLanes - 1); x < hi; x += kLanes) {
            i8 any_lane{};
            for (size_t v = 0; v < size_t(V); ++v) {
                const i8 px = G::pixel(int(v)) + x;
                covered[v] = (px >= lane_begin) & (px < lane_end);
                any_lane |= covered[v];
            }
            if (any(any_lane)) on_group(y, x, covered);
        }
    }
}

}  // namespace softraster
