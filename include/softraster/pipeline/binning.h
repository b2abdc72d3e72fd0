// Stage 6, binning: the front end's last stage. Each triangle that survives clipping and
// culling is appended to the bin of every tile its bounds touch (the pixels with a sample in
// its box, sample_pattern.h) and none of its edges leaves wholly outside, so that later each
// tile is drawn by one thread from its own list.
//
// Following Mesa llvmpipe (lp_setup -> lp_scene -> lp_rast): the picture is cut into 64x64
// tiles; one thread at a time owns a tile and draws its triangles in draw order, so no two
// threads ever write the same pixel and no locks are needed.
//
// The triangles of a draw are binned in chunks, in parallel; each chunk groups its
// triangles by tile (a counting sort) keeping their order, so walking the chunks in order
// and, in each, the tile's slice gives the tile's triangles in draw order. A chunk counts
// only the rectangle of tiles its triangles touch, not the whole grid: a scene of many small
// objects then costs per triangle, not per draw and tile.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "softraster/cache_line_allocator.h"
#include "softraster/pipeline/culling.h"
#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/primitive_assembly.h"
#include "softraster/pipeline/sample_pattern.h"
#include "softraster/pipeline/simd.h"
#include "softraster/pipeline/simd_avx2.h"
#include "softraster/pipeline/vertex_processing.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <immintrin.h>
#endif

namespace softraster {

// Where one thread's bins of a batch live (Context::execute_batch): each chunk's arrays
// (TriangleBin) taken one after another from blocks kept from batch to batch, and all given
// back at once when the next batch starts (reset), as the post-transform vertices are
// (Context::place_post_transform). The tile back ends read them within the same batch. With
// arrays of its own, kept by the draw from frame to frame, a small draw's three arrays were
// scattered over the heap, and each frame's front end first had to fetch their lines from
// memory (docs/performance.md, "Bins in batch memory"). One per thread, on lines of its own.
class alignas(kCacheLine) BinMemory {
public:
    // Room for `count` values of T, aligned for it and not initialized.
    template <class T>
    std::span<T> take(size_t count) {
        static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T> && alignof(T) <= alignof(std::max_align_t));
        return {reinterpret_cast<T*>(take_bytes(count * sizeof(T), alignof(T))), count};
    }
    // Everything taken is free again (the blocks are kept).
    void reset() { block_ = 0, used_ = 0; }

private:
    static constexpr size_t kBlock = size_t(256) << 10;
    std::byte* take_bytes(size_t bytes, size_t align) {
        for (;; ++block_, used_ = 0) {
            if (block_ == blocks_.size()) {  // (a block of its own for an array bigger than kBlock)
                const size_t size = std::max(kBlock, bytes);
                blocks_.push_back({std::make_unique_for_overwrite<std::byte[]>(size), size});
            }
            const size_t at = (used_ + align - 1) & ~(align - 1);
            if (at + bytes <= blocks_[block_].size) {
                used_ = at + bytes;
                return blocks_[block_].memory.get() + at;
            }
        }
    }
    // (From the C library as it comes, not on lines of their own: the blocks are big, so
    // only their ends could share a line, and aligned to lines bench_many_spheres took 1% to
    // 2% longer at one thread and at two, docs/performance.md.)
    struct Block {
        std::unique_ptr<std::byte[]> memory;
        size_t size;
    };
    std::vector<Block> blocks_;
    size_t block_ = 0, used_ = 0;  // the block taken from, and its bytes taken
};

template <int N>
struct TriangleBin {
    std::vector<ShadedVertex<N>> clipped;  // vertices the clipper made
    TileRange range;                       // the tiles this chunk's triangles touch
    // In the BinMemory the chunk was binned with, valid until its reset:
    std::span<TriangleRef> refs;      // grouped by tile of `range`, draw order within each
    std::span<uint32_t> tile_begin;   // local tile k's refs: [tile_begin[k], tile_begin[k + 1])
    // Per local tile: the pixels its triangles cover, summed (add_to_tiles: exact for large
    // triangles, else each one's area, at most its bounds within the tile), an estimate of
    // the overdraw (hidden_surface_removal.h).
    std::span<float> covered_area;

    struct Pending {  // a (tile, triangle) pair before grouping
        uint16_t tx, ty;
        float area;
        TriangleRef ref;
    };
    std::vector<Pending, CacheLineAllocator<Pending>> pending;  // (a thread's scratch: bin_pending)

    const ShadedVertex<N>& vertex(uint32_t i, const ShadedVertex<N>* post) const { return corner_vertex(i, post, clipped); }
    // The chunk's triangles in tile (tx, ty), in draw order.
    std::span<const TriangleRef> triangles_in(int tx, int ty) const {
        const int k = range.local(tx, ty);
        if (k < 0) return {};
        return refs.subspan(tile_begin[size_t(k)], tile_begin[size_t(k) + 1] - tile_begin[size_t(k)]);
    }
};

// The area (in pixels) of the triangle with corners p[0..2] (snapped window coordinates, in
// 1/256 pixel) inside rectangle [x0, x1] x [y0, y1] (the same units): the triangle clipped
// to each side in turn (Sutherland-Hodgman), then the shoelace formula.
inline double clipped_area(const std::array<double, 3>& px, const std::array<double, 3>& py, double x0, double y0, double x1, double y1) {
    struct P {
        double x, y;
    };
    std::array<P, 8> a{}, b{};
    int n = 3;
    for (int k = 0; k < 3; ++k) a[size_t(k)] = {px[size_t(k)], py[size_t(k)]};
    // side k keeps the points where inside(p) >= 0: x - x0, x1 - x, y - y0, y1 - y
    auto inside = [&](int side, const P& p) { return side == 0 ? p.x - x0 : side == 1 ? x1 - p.x : side == 2 ? p.y - y0 : y1 - p.y; };
    for (int side = 0; side < 4 && n > 0; ++side) {
        int m = 0;
        for (int k = 0; k < n; ++k) {
            const P& p = a[size_t(k)];
            const P& q = a[size_t((k + 1) % n)];
            const double dp = inside(side, p), dq = inside(side, q);
            if (dp >= 0) b[size_t(m++)] = p;
            if ((dp >= 0) != (dq >= 0)) {  // the side crosses pq
                const double t = dp / (dp - dq);
                b[size_t(m++)] = {p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t};
            }
        }
        n = m;
        a = b;
    }
    double twice = 0;
    for (int k = 0; k < n; ++k) twice += a[size_t(k)].x * a[size_t((k + 1) % n)].y - a[size_t((k + 1) % n)].x * a[size_t(k)].y;
    return std::abs(twice) * 0.5 / double(kSubpixelOne * kSubpixelOne);
}

// A triangle whose bounds span at least this many tiles across or down is large: it skips
// the tiles it does not reach and has its area in each tile computed exactly (clipped_area).
// A smaller one (most of a detailed mesh's) costs only its bounds: it goes to each tile they
// touch and counts its area, at most its bounds within the tile.
inline constexpr int kLargeTriangleTiles = 3;

// Edge k of the triangle with corners (xs[i], ys[i]) in snapped window coordinates, from
// corner k to the next, at point (px, py): E = (e.x)(P.y - k.y) - (e.y)(P.x - k.x), of the
// sign of the triangle's signed area inside (E at the third corner is area2). T: int64_t for
// corners anywhere in the guard band, int32_t where they are known to lie close together.
template <class T>
T edge_at(const T (&xs)[3], const T (&ys)[3], int k, T px, T py) {
    const int n = k < 2 ? k + 1 : 0;
    return (xs[n] - xs[k]) * (py - ys[k]) - (ys[n] - ys[k]) * (px - xs[k]);
}

// Appends a large triangle (add_to_tiles) to the tiles of `grid` in tiles [tx0, tx1] x
// [ty0, ty1] that it may cover: a tile that one of its edges leaves wholly outside (the
// tile's four corners strictly outside) holds none of its samples and is skipped. Each tile
// gets the triangle's area within it (and within the picture, for a tile at its edge).
template <int N, class V>
[[gnu::noinline]] void add_large_to_tiles(TriangleBin<N>& bin, const TileGrid& grid, TriangleRef ref, const V& a, const V& b, const V& c,
                                          int tx0, int ty0, int tx1, int ty1, int64_t area2) {
    const int64_t xs[3] = {a.X, b.X, c.X}, ys[3] = {a.Y, b.Y, c.Y};
    const int64_t sign = area2 < 0 ? -1 : 1;
    auto outside_one_edge = [&](int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
        for (int k = 0; k < 3; ++k) {
            auto out = [&](int64_t x, int64_t y) { return sign * edge_at(xs, ys, k, x, y) < 0; };
            if (out(x0, y0) && out(x1, y0) && out(x0, y1) && out(x1, y1)) return true;
        }
        return false;
    };
    const std::array<double, 3> px = {double(a.X), double(b.X), double(c.X)}, py = {double(a.Y), double(b.Y), double(c.Y)};
    const int64_t right = int64_t(grid.width) * kSubpixelOne, bottom = int64_t(grid.height) * kSubpixelOne;
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            // The tile's samples lie in its pixels' squares: [64 tx, 64 (tx + 1)] pixels.
            const int64_t x0 = int64_t(tx) * kTileSize * kSubpixelOne, x1 = x0 + kTileSize * kSubpixelOne;
            const int64_t y0 = int64_t(ty) * kTileSize * kSubpixelOne, y1 = y0 + kTileSize * kSubpixelOne;
            if (outside_one_edge(x0, y0, x1, y1)) continue;
            const double in = clipped_area(px, py, double(x0), double(y0), double(std::min(x1, right)), double(std::min(y1, bottom)));
            bin.pending.push_back({uint16_t(tx), uint16_t(ty), float(in), ref});
        }
}

// Appends triangle `ref` with corners a, b, c (snapped window coordinates), whose samples
// may lie in pixels `bounds` and whose snapped area is |area2| / 2 in 1/256-pixel units
// squared, to every tile of `grid` the bounds touch, with the area it covers there for the
// hidden-surface decision (hidden_surface_removal.h); a large one only to the tiles it may
// cover (add_large_to_tiles). `tiles` grows to hold the tiles its bounds touch (a large
// triangle may skip its corner tiles: the chunk's range holds them all the same, as it
// needs only hold them). (The caller keeps `tiles` in a local, not in the bin: there, each
// triangle's pending store could alias it, and it would be loaded and stored each time.)
template <int N, class V>
void add_to_tiles(TriangleBin<N>& bin, TileBounds& tiles, const TileGrid& grid, TriangleRef ref, const V& a, const V& b, const V& c, Rect bounds,
                  int64_t area2) {
    const Rect r = intersect(bounds, Rect{0, 0, grid.width, grid.height});
    if (r.empty()) return;
    const int tx0 = r.x0 / kTileSize, tx1 = (r.x1 - 1) / kTileSize, ty0 = r.y0 / kTileSize, ty1 = (r.y1 - 1) / kTileSize;
    tiles.include(tx0, ty0, tx1, ty1);
    const float area = float(area2 < 0 ? -area2 : area2) * (0.5f / float(kSubpixelOne * kSubpixelOne));
    if (tx0 == tx1 && ty0 == ty1) {  // in one tile, as most triangles of a detailed mesh
        bin.pending.push_back({uint16_t(tx0), uint16_t(ty0), std::min(float((r.x1 - r.x0) * (r.y1 - r.y0)), area), ref});
        return;
    }
    if (area2 != 0 && (tx1 - tx0 + 1 >= kLargeTriangleTiles || ty1 - ty0 + 1 >= kLargeTriangleTiles))
        return add_large_to_tiles(bin, grid, ref, a, b, c, tx0, ty0, tx1, ty1, area2);
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const int w = std::min(r.x1, (tx + 1) * kTileSize) - std::max(r.x0, tx * kTileSize);
            const int h = std::min(r.y1, (ty + 1) * kTileSize) - std::max(r.y0, ty * kTileSize);
            bin.pending.push_back({uint16_t(tx), uint16_t(ty), std::min(float(w * h), area), ref});
        }
}

// Groups the pending triangles by tile, keeping their order (a counting sort over the
// chunk's range of tiles), into arrays taken from `memory`.
template <int N>
void group_by_tile(TriangleBin<N>& bin, BinMemory& memory) {
    const size_t tiles = size_t(bin.range.count());
    bin.tile_begin = memory.take<uint32_t>(tiles + 1);
    bin.covered_area = memory.take<float>(tiles);
    std::fill(bin.tile_begin.begin(), bin.tile_begin.end(), 0u);
    std::fill(bin.covered_area.begin(), bin.covered_area.end(), 0.0f);
    // Every pending tile lies in the range: its index there needs no check.
    const TileRange& r = bin.range;
    auto local = [&](const auto& p) { return size_t((p.ty - r.y0) * r.width() + (p.tx - r.x0)); };
    // Neighbouring triangles of a mesh mostly share a tile: each run of pairs in one tile
    // has its count and area summed in registers and stored once, where a load and a store
    // per pair chained each pair's sum behind the last one's store. (The area is added pair
    // by pair onto the tile's sum, in the same order: the same bits.)
    const auto* p = bin.pending.data();
    const size_t n = bin.pending.size();
    for (size_t i = 0; i < n;) {
        const size_t k = local(p[i]);
        uint32_t count = 0;
        float area = bin.covered_area[k];
        do area += p[i].area, ++count, ++i;
        while (i < n && local(p[i]) == k);
        bin.tile_begin[k + 1] += count;
        bin.covered_area[k] = area;
    }
    for (size_t k = 1; k <= tiles; ++k) bin.tile_begin[k] += bin.tile_begin[k - 1];
    bin.refs = memory.take<TriangleRef>(n);  // (every one written below)
    const std::span<uint32_t> cursor = bin.tile_begin;  // reuse: advance each start, then shift back
    for (size_t i = 0; i < n;) {
        const size_t k = local(p[i]);
        uint32_t at = cursor[k];
        do bin.refs[at++] = p[i++].ref;
        while (i < n && local(p[i]) == k);
        cursor[k] = at;
    }
    for (size_t k = tiles; k > 0; --k) bin.tile_begin[k] = bin.tile_begin[k - 1];
    bin.tile_begin[0] = 0;
}

// The most (tile, triangle) pairs a thread keeps room for between draws (bin_pending): 1.25 MB.
inline constexpr size_t kKeptPending = size_t(1) << 16;

// Fills the bin's pending (tile, triangle) pairs (fill() calls add_to_tiles), then groups
// them by tile into `memory`. The pending list is scratch until then: one per thread, kept
// from draw to draw (a small draw's own list was an allocation or more per draw) unless a
// huge chunk grew it, with room for `expected` pairs up front.
template <int N, class Fill>
void bin_pending(TriangleBin<N>& bin, BinMemory& memory, size_t expected, Fill&& fill) {
    static thread_local std::vector<typename TriangleBin<N>::Pending, CacheLineAllocator<typename TriangleBin<N>::Pending>> scratch;
    bin.pending.swap(scratch);
    bin.pending.clear();
    bin.pending.reserve(expected);
    fill();
    group_by_tile(bin, memory);
    bin.pending.swap(scratch);
    if (scratch.capacity() > kKeptPending) scratch = {};
}

// Whether a triangle (corners a, b, c in snapped window coordinates, twice its signed area
// area2) whose pixel bounds `r` are at most two pixels each way certainly covers none of their
// samples, in a single-sampled framebuffer (s one point): no pixel center of the bounds is
// inside its three edges or on one. Such a triangle (a third of those that reach a tile in
// a mesh about as fine as the pixels) would cost its tile a setup and a walk over its bounds
// for nothing. Its corners lie within three pixels of each other, so each edge function at
// a center is a product of numbers below 2^11: exact in 32 bits, and the four centers of the
// 2x2 block are tested without a branch. (A center on an edge counts as inside whatever the
// fill rule, so the test drops nothing the rasterizer would draw.)
template <class V>
bool covers_no_center(const V& a, const V& b, const V& c, const Rect& r, const SampleExtent& s, int64_t area2) {
    if (s.x_lo != s.x_hi || s.y_lo != s.y_hi || r.x1 - r.x0 > 2 || r.y1 - r.y0 > 2) return false;
    // The edges (edge_at) relative to the first center, (r.x0, r.y0)'s.
    const int32_t ox = r.x0 * int32_t(kSubpixelOne) + s.x_lo, oy = r.y0 * int32_t(kSubpixelOne) + s.y_lo;
    const int32_t xs[3] = {a.X - ox, b.X - ox, c.X - ox}, ys[3] = {a.Y - oy, b.Y - oy, c.Y - oy};
    const int32_t sign = area2 < 0 ? -1 : 1;
    // Center k of the 2x2 block lies (k & 1, k >> 1) pixels from the first. Edge e's value
    // there (edge_at, times the sign) is its value at the first center plus a pixel's step
    // right, -dy, and down, +dx, each times 256: the four values of an edge are its first and
    // three sums, and a center is outside where the OR of its three edges' values is negative.
    int32_t outside[4] = {0, 0, 0, 0};
    for (int e = 0; e < 3; ++e) {
        const int n = e < 2 ? e + 1 : 0;
        const int32_t dx = sign * (xs[n] - xs[e]), dy = sign * (ys[n] - ys[e]);
        const int32_t first = dy * xs[e] - dx * ys[e];  // (edge_at at (0, 0))
        const int32_t right = -dy * int32_t(kSubpixelOne), down = dx * int32_t(kSubpixelOne);
        outside[0] |= first, outside[1] |= first + right, outside[2] |= first + down, outside[3] |= first + right + down;
    }
    // (A center past the bounds needs no mask: it lies beyond the corners' box, so outside
    // an edge of a triangle that has an area, which binning's triangles have.)
    return (outside[0] & outside[1] & outside[2] & outside[3]) < 0;
}

// ---- eight triangles at a time
//
// Most triangles of a detailed mesh lie inside every clip plane and within one tile, and
// each takes the same few tests: finite corners, outcodes, winding, bounds, a covered
// center, its tile. Per triangle those tests are branches in an order a mesh makes hard to
// predict; here they run on eight triangles at once, in lanes, and only what they decide is
// done per triangle: nothing, one pending pair, or (for one that crosses a clip plane,
// reaches more than one tile, or has corners 2^15 subpixels or more apart) the one-at-a-time
// path above. The decisions are the same (the
// Binning.EightAtATimeSameAsOneAtATime test).

// Corner k of eight triangles, one per lane: snapped position, outcode, and finiteness in
// the low byte (ClipInfo's fields from X on).
struct Corners8 {
    simd::i8 X[3], Y[3], outcode[3], finite[3];
};
template <bool Wide>
inline void load_corners8(const uint32_t* indices, const ClipInfo* clip, Corners8& out) {
    for (int t = 0; t < simd::kLanes; ++t)
        for (int k = 0; k < 3; ++k) {
            const ClipInfo& c = clip[indices[3 * t + k]];
            out.X[k][t] = c.X, out.Y[k][t] = c.Y, out.outcode[k][t] = int32_t(c.outcode), out.finite[k][t] = c.finite;
        }
}
#if SOFTRASTER_HAS_AVX2_PATH
// The 16 bytes from X on of each corner, triangles t and t + 4 in one register, then
// simd::transpose4x4_halves: 24 loads and 12 shuffles for 96 fields.
template <>
[[gnu::target("avx2")]] inline void load_corners8<true>(const uint32_t* indices, const ClipInfo* clip, Corners8& out) {
    static_assert(sizeof(ClipInfo) == 32 && offsetof(ClipInfo, X) == 16 && offsetof(ClipInfo, Y) == 20 && offsetof(ClipInfo, outcode) == 24 &&
                  offsetof(ClipInfo, finite) == 28);
    for (int k = 0; k < 3; ++k) {
        __m256i r[4];
        for (int t = 0; t < 4; ++t) {
            const auto* low = reinterpret_cast<const __m128i*>(&clip[indices[3 * t + k]].X);
            const auto* high = reinterpret_cast<const __m128i*>(&clip[indices[3 * (t + 4) + k]].X);
            r[t] = _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128(low)), _mm_loadu_si128(high), 1);
        }
        simd::transpose4x4_halves(r);
        out.X[k] = simd::i8(r[0]), out.Y[k] = simd::i8(r[1]), out.outcode[k] = simd::i8(r[2]), out.finite[k] = simd::i8(r[3]);
    }
}
#endif

// What binning does with each of eight triangles, and for a triangle in one tile, the tile
// and its pending area.
enum BinVerdict : int32_t { kDrop = 0, kOneTile = 1, kOneAtATime = 2 };
struct Verdicts8 {
    simd::i8 verdict, tx, ty;
    simd::f8 area;
};
// The tests of bin_triangles' one-at-a-time path (assemble_triangle, the winding filter,
// pixel_bounds, covers_no_center, add_to_tiles' one-tile case), in the same order, on lanes.
// Where a triangle's corners lie within 2^15 (128 pixels) of each other each way, its edge
// products fit in 32 bits, so area2 and the edges are exact in 32-bit lanes; others go one
// at a time. (The arithmetic is unsigned, which wraps: lanes it is not exact in are not used.)
inline void binning_verdicts8(const Corners8& c, const SampleExtent& s, const WindingFilter& windings, const TileGrid& grid, Verdicts8& out) {
    using simd::i8, simd::f8, simd::select, simd::splat_i;
    using u8 = uint32_t __attribute__((vector_size(32)));
    auto u = [](const i8& v) { return std::bit_cast<u8>(v); };
    auto i = [](const u8& v) { return std::bit_cast<i8>(v); };
    auto min = [](const i8& a, const i8& b) { return select(a < b, a, b); };
    auto max = [](const i8& a, const i8& b) { return select(a > b, a, b); };
    const i8 finite = ((c.finite[0] & c.finite[1] & c.finite[2]) & 0xff) != 0;
    const i8 outside_one = (c.outcode[0] & c.outcode[1] & c.outcode[2]) != 0;
    const i8 clipped = (c.outcode[0] | c.outcode[1] | c.outcode[2]) != 0;
    const i8 x_lo = min(min(c.X[0], c.X[1]), c.X[2]), x_hi = max(max(c.X[0], c.X[1]), c.X[2]);
    const i8 y_lo = min(min(c.Y[0], c.Y[1]), c.Y[2]), y_hi = max(max(c.Y[0], c.Y[1]), c.Y[2]);
    const i8 near = (i(u(x_hi) - u(x_lo)) < (1 << 15)) & (i(u(y_hi) - u(y_lo)) < (1 << 15));  // (0 <= each: x_hi >= x_lo)
    // signed_area2, the winding filter.
    const i8 area2 = i((u(c.X[1]) - u(c.X[0])) * (u(c.Y[2]) - u(c.Y[0])) - (u(c.Y[1]) - u(c.Y[0])) * (u(c.X[2]) - u(c.X[0])));
    const i8 survives = ((area2 > 0) & splat_i(windings.keep_cw ? -1 : 0)) | ((area2 < 0) & splat_i(windings.keep_ccw ? -1 : 0));
    // pixel_bounds.
    constexpr int kRoundUp = int(kSubpixelOne) - 1;
    const i8 bx0 = (x_lo - s.x_hi + kRoundUp) >> kSubpixelBits, by0 = (y_lo - s.y_hi + kRoundUp) >> kSubpixelBits;
    const i8 bx1 = ((x_hi - s.x_lo) >> kSubpixelBits) + 1, by1 = ((y_hi - s.y_lo) >> kSubpixelBits) + 1;
    const i8 empty = (bx0 >= bx1) | (by0 >= by1);
    // covers_no_center, on bounds of at most 2x2 pixels of a single-sampled framebuffer.
    i8 no_center = splat_i(0);
    if (s.x_lo == s.x_hi && s.y_lo == s.y_hi) {
        const u8 ox = u(bx0 * int32_t(kSubpixelOne) + s.x_lo), oy = u(by0 * int32_t(kSubpixelOne) + s.y_lo);
        const u8 xs[3] = {u(c.X[0]) - ox, u(c.X[1]) - ox, u(c.X[2]) - ox}, ys[3] = {u(c.Y[0]) - oy, u(c.Y[1]) - oy, u(c.Y[2]) - oy};
        const u8 sign = u(select(area2 < 0, splat_i(-1), splat_i(1)));
        u8 outside[4] = {};
        for (int e = 0; e < 3; ++e) {
            const int n = e < 2 ? e + 1 : 0;
            const u8 dx = sign * (xs[n] - xs[e]), dy = sign * (ys[n] - ys[e]);
            const u8 first = dy * xs[e] - dx * ys[e], right = (0u - dy) * uint32_t(kSubpixelOne), down = dx * uint32_t(kSubpixelOne);
            outside[0] |= first, outside[1] |= first + right, outside[2] |= first + down, outside[3] |= first + right + down;
        }
        no_center = (bx1 - bx0 <= 2) & (by1 - by0 <= 2) & (i(outside[0] & outside[1] & outside[2] & outside[3]) < 0);
    }
    // add_to_tiles: the bounds within the picture, their tiles, the pending area.
    const i8 rx0 = max(bx0, splat_i(0)), ry0 = max(by0, splat_i(0)), rx1 = min(bx1, splat_i(grid.width)), ry1 = min(by1, splat_i(grid.height));
    const i8 off_picture = (rx0 >= rx1) | (ry0 >= ry1);
    static_assert(kTileSize == 64);  // (r.x0 >= 0 and r.x1 >= 1 where the bounds are not empty: the shifts are divisions)
    out.tx = rx0 >> 6, out.ty = ry0 >> 6;
    const i8 one_tile = (out.tx == ((rx1 - 1) >> 6)) & (out.ty == ((ry1 - 1) >> 6));
    const f8 area = simd::to_float(select(area2 < 0, i(0u - u(area2)), area2)) * (0.5f / float(kSubpixelOne * kSubpixelOne));  // (|area2|)
    const f8 box = simd::to_float(i(u(rx1 - rx0) * u(ry1 - ry0)));
    out.area = select(area < box, area, box);  // (std::min(box, area))
    const i8 drop = ~finite | outside_one | (~clipped & near & (~survives | empty | no_center | off_picture));
    const i8 alone = ~drop & (clipped | ~near | ~one_tile);
    out.verdict = select(drop, splat_i(kDrop), select(alone, splat_i(kOneAtATime), splat_i(kOneTile)));
}

// The front end's triangle half for one chunk of a draw, stage by stage: primitive assembly
// and clipping (primitive_assembly.h), culling (culling.h), binning. A triangle whose bounds
// hold no sample of the framebuffer's pattern (its extent `samples`, sample_pattern.h) is
// dropped, and so is a small one that covers none of its bounds' samples (covers_no_center).
// Eight triangles at a time (binning_verdicts8) unless Batched is false (the tests' reference).
template <bool Wide, int N, bool Batched = true>
void bin_triangles(std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipInfo* clip, const ClipPlanes& planes,
                   const Viewport& vp, const SampleExtent& samples, FaceState faces, FlatVaryings flat, const TileGrid& grid, TriangleBin<N>& bin,
                   BinMemory& memory) {
    bin.clipped.clear();
    const WindingFilter windings(faces);
    bin_pending(bin, memory, indices.size() / 3, [&] {  // (most triangles touch one tile)
        TileBounds tiles;
        auto emit = [&](TriangleRef ref, const auto& a, const auto& b, const auto& c) {
            const int64_t area2 = signed_area2(a.X, a.Y, b.X, b.Y, c.X, c.Y);
            if (!windings.survives(area2)) return;
            const Rect bounds = pixel_bounds(a, b, c, samples);
            if (bounds.empty() || covers_no_center(a, b, c, bounds, samples, area2)) return;
            add_to_tiles(bin, tiles, grid, ref, a, b, c, bounds, area2);
        };
        size_t i = 0;
        if constexpr (Batched) {
            ClipPolygon<N> poly;
            constexpr size_t kBatch = 3 * simd::kLanes;
            for (; i + kBatch <= indices.size(); i += kBatch) {
                const uint32_t* at = indices.data() + i;
                // (The next batch's corners into the cache meanwhile, as assemble_triangles.)
                if (i + 2 * kBatch <= indices.size())
                    for (size_t k = 0; k < simd::kLanes; ++k) __builtin_prefetch(clip + at[kBatch + 3 * k + 1]), __builtin_prefetch(clip + at[kBatch + 3 * k + 2]);
                Corners8 corners;
                load_corners8<Wide>(at, clip, corners);
                Verdicts8 v;
                binning_verdicts8(corners, samples, windings, grid, v);
                for (int t = 0; t < simd::kLanes; ++t) {
                    const uint32_t* ref = at + 3 * t;
                    if (v.verdict[t] == kOneTile) {
                        tiles.include(v.tx[t], v.ty[t], v.tx[t], v.ty[t]);
                        bin.pending.push_back({uint16_t(v.tx[t]), uint16_t(v.ty[t]), v.area[t], TriangleRef{{ref[0], ref[1], ref[2]}}});
                    } else if (v.verdict[t] == kOneAtATime) {
                        assemble_triangle(ref[0], ref[1], ref[2], post, clip, planes, vp, flat, bin.clipped, poly, emit);
                    }
                }
            }
        }
        assemble_triangles(indices.subspan(i), post, clip, planes, vp, flat, bin.clipped, emit);
        bin.range = tiles.range();
    });
}

}  // namespace softraster
