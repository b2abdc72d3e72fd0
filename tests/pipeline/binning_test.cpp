// Binning: every triangle that survives culling lands in exactly the tiles its sample bounds
// touch (a large one: those it overlaps), in draw order within each tile, and nowhere else;
// the per-tile covered area is the sum the tiles' triangles contribute; a chunk counts only
// its own range of tiles; a small triangle that covers no sample is dropped, and no other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <malloc.h>
#include <random>
#include <type_traits>
#include <vector>

#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/draw_commands.h"
#include "softraster/pipeline/rasterization.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 256, H = 256;  // the viewport random_triangle maps to: 4 x 4 tiles

// The clip parts of n vertices v inside every clip plane and finite (as finish_vertex made
// them, which the tests' vertices come from): binning reads their flags and snapped positions.
std::vector<ClipInfo> inside(const ShadedVertex<1>* v, size_t n) {
    std::vector<ClipInfo> clip(n);
    for (size_t i = 0; i < n; ++i) clip[i].X = v[i].X, clip[i].Y = v[i].Y;
    return clip;
}

struct Expected {
    std::vector<std::vector<uint32_t>> triangles;  // per tile, in draw order
    std::vector<double> area;                       // per tile
    std::vector<std::vector<uint32_t>> maybe;       // per tile: may be listed too (they touch it)
};

// The area of triangle abc inside rectangle [x0, x1] x [y0, y1] (pixels), integrated column
// by column: at each column's middle, the span of y inside all three edges and the rectangle.
double area_in_rect(const ShadedVertex<1>& a, const ShadedVertex<1>& b, const ShadedVertex<1>& c, double x0, double y0, double x1, double y1) {
    const double px[3] = {a.X / 256.0, b.X / 256.0, c.X / 256.0}, py[3] = {a.Y / 256.0, b.Y / 256.0, c.Y / 256.0};
    const double s = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]) < 0 ? -1.0 : 1.0;
    constexpr int kColumns = 4096;
    const double dx = (x1 - x0) / kColumns;
    double sum = 0;
    for (int i = 0; i < kColumns; ++i) {
        const double x = x0 + (i + 0.5) * dx;
        double lo = y0, hi = y1;
        for (int k = 0; k < 3; ++k) {  // s E(x, y) = A y + B >= 0 inside edge k
            const double ex = px[(k + 1) % 3] - px[k], ey = py[(k + 1) % 3] - py[k];
            const double A = s * ex, B = s * (-ex * py[k] - ey * (x - px[k]));
            if (A > 0) lo = std::max(lo, -B / A);
            else if (A < 0) hi = std::min(hi, -B / A);
            else if (B < 0) hi = lo;
        }
        sum += std::max(0.0, hi - lo) * dx;
    }
    return sum;
}

// Whether the rasterizer (rasterization.h, 64-bit edges) finds a sample of triangle abc
// covered, anywhere in the viewport, single-sampled.
bool covers_a_sample(const ShadedVertex<1>& a, const ShadedVertex<1>& b, const ShadedVertex<1>& c) {
    TriangleSetup<1> t;
    if (!setup_triangle<1>(a, b, c, FrontFace::CCW, Rect{0, 0, W, H}, t)) return false;
    bool covered = false;
    rasterize_triangle<1>(t, t.bounds, [&](const CoveredPixel<1>&) { covered = true; });
    return covered;
}

// Whether a pixel center of the triangle's bounds is inside its three edges or on one, in
// 64-bit integers.
bool touches_a_center(const ShadedVertex<1>& a, const ShadedVertex<1>& b, const ShadedVertex<1>& c) {
    const Rect r = pixel_bounds<1>(a, b, c);
    const ShadedVertex<1>* v[3] = {&a, &b, &c};
    const int64_t area2 = signed_area2(a.X, a.Y, b.X, b.Y, c.X, c.Y);
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const int64_t cx = int64_t(x) * 256 + 128, cy = int64_t(y) * 256 + 128;
            int inside = 0;
            for (int e = 0; e < 3; ++e) {
                const ShadedVertex<1>&p = *v[e], &q = *v[(e + 1) % 3];
                const int64_t edge = int64_t(q.X - p.X) * (cy - p.Y) - int64_t(q.Y - p.Y) * (cx - p.X);
                inside += area2 > 0 ? edge >= 0 : edge <= 0;
            }
            if (inside == 3) return true;
        }
    return false;
}

// Whether binning drops the triangle though its bounds hold samples: one at most two pixels
// each way with no center inside or on an edge (covers_no_center).
bool dropped_as_empty(const ShadedVertex<1>& a, const ShadedVertex<1>& b, const ShadedVertex<1>& c) {
    const Rect r = pixel_bounds<1>(a, b, c);
    return r.x1 - r.x0 <= 2 && r.y1 - r.y0 <= 2 && !touches_a_center(a, b, c);
}

// What binning must produce, computed directly: each triangle tested against each tile. A
// large triangle (its bounds span kLargeTriangleTiles tiles or more) is in the tiles it
// overlaps, with the area it covers there; a small one in every tile its bounds touch, with
// its area, at most its bounds within the tile.
Expected expected_bins(const std::vector<ShadedVertex<1>>& post, FaceState faces, const TileGrid& grid) {
    Expected e{std::vector<std::vector<uint32_t>>(size_t(grid.count())), std::vector<double>(size_t(grid.count()), 0.0),
               std::vector<std::vector<uint32_t>>(size_t(grid.count()))};
    for (uint32_t t = 0; t < post.size() / 3; ++t) {
        const ShadedVertex<1>&a = post[3 * t], &b = post[3 * t + 1], &c = post[3 * t + 2];
        const int64_t area2 = signed_area2(a.X, a.Y, b.X, b.Y, c.X, c.Y);
        if (!WindingFilter(faces).survives(area2)) continue;
        const Rect bounds = intersect(pixel_bounds<1>(a, b, c), Rect{0, 0, W, H});
        if (bounds.empty() || dropped_as_empty(a, b, c)) continue;
        const bool large = (bounds.x1 - 1) / kTileSize - bounds.x0 / kTileSize + 1 >= kLargeTriangleTiles ||
                           (bounds.y1 - 1) / kTileSize - bounds.y0 / kTileSize + 1 >= kLargeTriangleTiles;
        for (int tile = 0; tile < grid.count(); ++tile) {
            const Rect in = intersect(bounds, grid.tile_rect(tile));
            if (in.empty()) continue;
            if (large) {
                const Rect r = grid.tile_rect(tile);
                const double covered = area_in_rect(a, b, c, r.x0, r.y0, r.x1, r.y1);
                if (covered < 1e-3) {  // apart from the tile, or (nearly) touching it: then binning may keep it
                    if (area_in_rect(a, b, c, r.x0 - 0.01, r.y0 - 0.01, r.x1 + 0.01, r.y1 + 0.01) > 0) e.maybe[size_t(tile)].push_back(t);
                    continue;
                }
                e.triangles[size_t(tile)].push_back(t);
                e.area[size_t(tile)] += covered;
                continue;
            }
            e.triangles[size_t(tile)].push_back(t);
            const double w = in.x1 - in.x0, h = in.y1 - in.y0;
            e.area[size_t(tile)] += std::min(w * h, double(std::abs(area2)) / (2.0 * 256.0 * 256.0));
        }
    }
    return e;
}

}  // namespace

// A batch's bins memory hands out room that no other take overlaps, aligned for its type,
// arrays bigger than a block too; after a reset it hands out the same room again.
TEST(BinMemory, TakesRoomOfItsOwnAndGivesItBackAtReset) {
    BinMemory memory;
    struct Taken {
        const std::byte *begin, *end;
    };
    std::vector<Taken> taken;
    auto take = [&](size_t count, auto type) {
        using T = decltype(type);
        const std::span<T> s = memory.take<T>(count);
        EXPECT_EQ(s.size(), count);
        EXPECT_EQ(reinterpret_cast<uintptr_t>(s.data()) % alignof(T), 0u);
        for (size_t i = 0; i < count; ++i) s[i] = T{};  // (writable: ASan sees a write past a block)
        if (count > 0) taken.push_back({reinterpret_cast<const std::byte*>(s.data()), reinterpret_cast<const std::byte*>(s.data() + count)});
        return s.data();
    };
    std::mt19937 rng(3);
    const void* first = take(3, uint8_t{});
    for (int k = 0; k < 2000; ++k) {
        const size_t count = rng() % 7 == 0 ? 0 : rng() % 40 == 0 ? 70000 : rng() % 300;  // (70,000 refs: a block's worth and more)
        if (k % 3 == 0) take(count, uint32_t{});
        else if (k % 3 == 1) take(count, float{});
        else take(count, TriangleRef{});
    }
    std::sort(taken.begin(), taken.end(), [](const Taken& a, const Taken& b) { return a.begin < b.begin; });
    for (size_t i = 1; i < taken.size(); ++i) ASSERT_LE(taken[i - 1].end, taken[i].begin) << "two takes overlap";
    memory.reset();
    EXPECT_EQ(memory.take<uint8_t>(3).data(), first);
}

// A thread's scratch of the front end, written at every draw, takes whole cache lines of its
// own (cache_line_allocator.h): it starts on a line, and its block reaches the end of its
// last line, so the C library places nothing else there, for this thread or another.
static_assert(std::is_same_v<decltype(TriangleBin<3>::pending)::allocator_type, CacheLineAllocator<TriangleBin<3>::Pending>>);
static_assert(std::is_same_v<std::remove_reference_t<decltype(small_draw_clip_parts())>::allocator_type, CacheLineAllocator<ClipInfo>>);
TEST(CacheLineAllocator, TakesWholeLinesOfItsOwn) {
    struct Twenty {  // (a Pending's size: 20 bytes, not a divisor of a line)
        uint32_t v[5];
    };
    CacheLineAllocator<Twenty> lines;
    for (size_t n = 1; n <= 40; ++n) {
        Twenty* p = lines.allocate(n);
        const auto begin = reinterpret_cast<uintptr_t>(p), end = (begin + n * sizeof(Twenty) + 63) / 64 * 64;
        EXPECT_EQ(begin % 64, 0u) << n;
        EXPECT_GE(malloc_usable_size(p), end - begin) << n << " elements";
        lines.deallocate(p, n);
    }
}

// The blocks of the post-transform vertices (Context) do the same, their bytes not
// initialized. (glibc leaves a block aligned to a line room to the
// end of its last line even unrounded; the rounding is for allocators that do not.)
TEST(CacheLineAllocator, BlocksTakeWholeLinesOfTheirOwn) {
    for (size_t n = 1; n <= 1000; n += 13) {
        const CacheLineBlock block(n);
        EXPECT_EQ(block.size(), n);
        EXPECT_EQ(reinterpret_cast<uintptr_t>(block.data()) % 64, 0u) << n;
        EXPECT_GE(malloc_usable_size(block.data()), (n + 63) / 64 * 64) << n << " bytes";
    }
    const CacheLineBlock none;
    EXPECT_EQ(none.data(), nullptr);
    EXPECT_EQ(none.size(), 0u);
}

TEST(Binning, EachTriangleInTheTilesItReachesInDrawOrder) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0, 1);
    const TileGrid grid(W, H);
    for (int round = 0; round < 20; ++round) {
        // Triangles of every size, some reaching past the viewport, in one corner of it
        // in some rounds (so that the chunk's range of tiles is smaller than the grid).
        const bool corner = round % 2 == 1;
        std::vector<ShadedVertex<1>> post;
        for (int k = 0; k < 400; ++k) {
            std::array<ShadedVertex<1>, 3> p;
            const float size = k % 10 == 0 ? 200.0f : 1.0f + 40.0f * u(rng) * u(rng);
            const float cx = corner ? 150 + 100 * u(rng) : -20 + 296 * u(rng), cy = corner ? 160 + 90 * u(rng) : -20 + 296 * u(rng);
            if (!random_triangle(rng, cx, cy, size, size, p)) continue;
            post.insert(post.end(), p.begin(), p.end());
        }
        std::vector<uint32_t> indices(post.size());
        for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        const FaceState faces{round % 3 == 0 ? CullMode::None : CullMode::Back, FrontFace::CCW};
        TriangleBin<1> bin;
        BinMemory memory;
        bin_triangles<false>(indices, post.data(), inside(post.data(), post.size()).data(), ClipPlanes::for_viewport(W, H), Viewport{W, H}, sample_extent<1>(), faces, FlatVaryings{}, grid, bin,
                             memory);

        const Expected e = expected_bins(post, faces, grid);
        size_t listed = 0;
        for (int tile = 0; tile < grid.count(); ++tile) {
            const int tx = tile % grid.tiles_x, ty = tile / grid.tiles_x;
            std::vector<uint32_t> got;
            for (const TriangleRef& r : bin.triangles_in(tx, ty)) {
                ASSERT_EQ(r.v[0] % 3, 0u);  // no triangle here needs the clipper
                listed += 1;
                const std::vector<uint32_t>& maybe = e.maybe[size_t(tile)];
                if (std::find(maybe.begin(), maybe.end(), r.v[0] / 3) == maybe.end()) got.push_back(r.v[0] / 3);
            }
            ASSERT_EQ(got, e.triangles[size_t(tile)]) << "round " << round << " tile " << tile;
            const int k = bin.range.local(tx, ty);
            if (got.empty()) continue;
            ASSERT_GE(k, 0) << "tile " << tile << " has triangles outside the chunk's range";
            EXPECT_NEAR(bin.covered_area[size_t(k)], e.area[size_t(tile)], 1e-3 * (1.0 + e.area[size_t(tile)]));
        }
        EXPECT_EQ(listed, bin.refs.size());
        if (corner) {
            EXPECT_LT(bin.range.count(), grid.count()) << "round " << round;
        }
        EXPECT_GT(listed, 150u);
    }
}

TEST(Binning, TriangleCoveringNoSampleIsDropped) {
    // Inside pixel (10, 10) but away from its center: no sample in its bounds, no tile.
    ShadedVertex<1> v[3];
    const glm::vec2 p[3] = {{10.1f, 10.1f}, {10.4f, 10.1f}, {10.1f, 10.4f}};
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(finish_vertex(ClipVertex<1>{window_to_clip(p[i].x, p[i].y, W, H), {}}, Viewport{W, H}, v[i]));
    const uint32_t idx[3] = {0, 1, 2};
    TriangleBin<1> bin;
    BinMemory memory;
    bin_triangles<false>(idx, v, inside(v, 3).data(), ClipPlanes::for_viewport(W, H), Viewport{W, H}, sample_extent<1>(), FaceState{CullMode::None, FrontFace::CCW}, FlatVaryings{},
                     TileGrid(W, H), bin, memory);
    EXPECT_TRUE(bin.refs.empty());
    EXPECT_EQ(bin.range.count(), 0);
}

TEST(Binning, SmallTriangleBetweenPixelCentersIsDropped) {
    // Its box holds the center of pixel (10, 10), (10.5, 10.5), but its long edge passes
    // short of it (x + y = 20.9): it covers no sample, and reaches no tile.
    ShadedVertex<1> v[3];
    const glm::vec2 p[3] = {{10.0f, 10.0f}, {10.9f, 10.0f}, {10.0f, 10.9f}};
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(finish_vertex(ClipVertex<1>{window_to_clip(p[i].x, p[i].y, W, H), {}}, Viewport{W, H}, v[i]));
    ASSERT_FALSE(pixel_bounds<1>(v[0], v[1], v[2]).empty());
    const uint32_t idx[3] = {0, 1, 2};
    TriangleBin<1> bin;
    BinMemory memory;
    bin_triangles<false>(idx, v, inside(v, 3).data(), ClipPlanes::for_viewport(W, H), Viewport{W, H}, sample_extent<1>(), FaceState{CullMode::None, FrontFace::CCW}, FlatVaryings{},
                  TileGrid(W, H), bin, memory);
    EXPECT_TRUE(bin.refs.empty());
}

// Tiny triangles, as a mesh finer than the pixels has: binning keeps each one that covers a
// sample, and each with a center on an edge (whichever edge owns it); it drops those whose
// bounds, at most two pixels each way, have no center inside or on an edge. With 4x MSAA it
// keeps every one whose bounds hold a sample.
TEST(Binning, DropsSmallTrianglesThatCoverNoSampleAndNoOther) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    const TileGrid grid(W, H);
    int dropped = 0, kept = 0, on_edge = 0;
    BinMemory memory;
    for (int k = 0; k < 20000; ++k) {
        memory.reset();
        std::array<ShadedVertex<1>, 3> p;
        if (k % 4 == 0) {  // corners on a quarter-pixel lattice: centers fall on edges
            const float x = float(8 + int(200 * u(rng))), y = float(8 + int(200 * u(rng)));
            for (auto& v : p) {
                const float px = x + 0.25f * float(int(12 * u(rng))), py = y + 0.25f * float(int(12 * u(rng)));
                ASSERT_TRUE(finish_vertex(ClipVertex<1>{window_to_clip(px, py, W, H), {}}, Viewport{W, H}, v));
            }
        } else if (!random_triangle(rng, 8 + 240 * u(rng), 8 + 240 * u(rng), 0.3f + 3 * u(rng), 0.3f + 3 * u(rng), p)) {
            continue;
        }
        const int64_t area2 = signed_area2(p[0].X, p[0].Y, p[1].X, p[1].Y, p[2].X, p[2].Y);
        if (area2 == 0) continue;
        const uint32_t idx[3] = {0, 1, 2};
        TriangleBin<1> bin;
        bin_triangles<false>(idx, p.data(), inside(p.data(), 3).data(), ClipPlanes::for_viewport(W, H), Viewport{W, H}, sample_extent<1>(), FaceState{CullMode::None, FrontFace::CCW},
                      FlatVaryings{}, grid, bin, memory);
        const Rect r = pixel_bounds<1>(p[0], p[1], p[2]);
        const bool covers = covers_a_sample(p[0], p[1], p[2]), touches = touches_a_center(p[0], p[1], p[2]);
        ASSERT_TRUE(touches || !covers) << "triangle " << k;
        const bool small = r.x1 - r.x0 <= 2 && r.y1 - r.y0 <= 2;
        ASSERT_EQ(bin.refs.empty(), r.empty() || (small && !touches)) << "triangle " << k;
        dropped += !r.empty() && bin.refs.empty();
        kept += !bin.refs.empty();
        on_edge += touches && !covers;  // kept for a center on an edge the fill rule gives away
        // 4x MSAA: no triangle whose bounds hold a sample is dropped
        TriangleBin<1> msaa;
        bin_triangles<false>(idx, p.data(), inside(p.data(), 3).data(), ClipPlanes::for_viewport(W, H), Viewport{W, H}, sample_extent<4>(), FaceState{CullMode::None, FrontFace::CCW},
                      FlatVaryings{}, grid, msaa, memory);
        ASSERT_EQ(msaa.refs.empty(), pixel_bounds<4>(p[0], p[1], p[2]).empty()) << "triangle " << k;
    }
    EXPECT_GT(dropped, 2000);
    EXPECT_GT(kept, 2000);
    EXPECT_GT(on_edge, 100);
}

// Binning eight triangles at a time (binning_verdicts8, on each CPU path) gives the bins one
// at a time gives, to the bit: triangles inside and crossing the clip planes, behind the eye,
// with a NaN corner, of both windings and none, from a hundredth of a pixel to past the guard
// band, in one tile or many or off the picture, each cull mode, single-sampled and 4x.
TEST(Binning, EightAtATimeSameAsOneAtATime) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    constexpr int kW = 300, kH = 200;  // (not whole tiles)
    const TileGrid grid(kW, kH);
    const ClipPlanes planes = ClipPlanes::for_viewport(kW, kH);
    const Viewport vp{kW, kH};
    size_t kinds[3] = {0, 0, 0};  // triangles binned in one tile, in several, none
    for (int round = 0; round < 60; ++round) {
        // Triangle soup: a center in clip space, corners around it at one of several scales.
        std::vector<ShadedVertex<1>> post;
        std::vector<ClipInfo> clip;
        const int triangles = 8 + round * 7;  // (batches of eight and tails)
        for (int t = 0; t < triangles; ++t) {
            const float scales[] = {0.0001f, 0.004f, 0.01f, 0.05f, 0.3f, 3.0f, 300.0f};
            const float scale = scales[size_t(rng() % 7)];
            const float cx = -1.3f + 2.6f * u(rng), cy = -1.3f + 2.6f * u(rng), w = u(rng) < 0.05f ? -0.5f : 0.5f + u(rng);
            for (int k = 0; k < 3; ++k) {
                ClipInfo c;
                c.position = glm::vec4((cx + scale * (u(rng) - 0.5f)) * w, (cy + scale * (u(rng) - 0.5f)) * w, (u(rng) - 0.5f) * w, w);
                if (rng() % 97 == 0) c.position.x = NAN;
                if (rng() % 89 == 0) c.position.w = 1e-4f * (u(rng) - 0.5f);  // near the eye: clipped or behind it
                clip.push_back(c);
                ShadedVertex<1> v;
                v.var[0] = u(rng);
                post.push_back(v);
            }
        }
        while (post.size() % 8) post.push_back({}), clip.push_back({});
        for (size_t k = 0; k < post.size(); k += 8) finish_vertices8_generic(&post[k], &clip[k], planes, vp);
        if (round == 0) {  // a triangle whose area2, 2^31, wraps to INT_MIN in a 32-bit lane (the lanes must not negate it)
            const int32_t corners[3][2] = {{0, 0}, {1 << 16, 0}, {0, 1 << 15}};
            for (int k = 0; k < 3; ++k) clip[size_t(k)].X = corners[k][0], clip[size_t(k)].Y = corners[k][1], clip[size_t(k)].outcode = 0, clip[size_t(k)].finite = true;
        }
        std::vector<uint32_t> indices(size_t(triangles) * 3);
        for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front})
            for (bool msaa : {false, true}) {
                const FaceState faces{cull, FrontFace::CCW};
                const SampleExtent samples = msaa ? sample_extent<4>() : sample_extent<1>();
                TriangleBin<1> one;
                BinMemory memory;
                bin_triangles<false, 1, false>(indices, post.data(), clip.data(), planes, vp, samples, faces, FlatVaryings{}, grid, one, memory);
                for (bool generic : {false, true}) {
                    simd::use_generic_path(generic);
                    TriangleBin<1> eight;
                    simd::on_best_path([&]<bool Wide>() {
                        bin_triangles<Wide>(indices, post.data(), clip.data(), planes, vp, samples, faces, FlatVaryings{}, grid, eight, memory);
                    });
                    const std::string what = "round " + std::to_string(round) + " cull " + std::to_string(int(cull)) + (msaa ? " 4x" : "") +
                                             (generic ? " generic" : "");
                    ASSERT_EQ(eight.refs.size(), one.refs.size()) << what;
                    for (size_t k = 0; k < one.refs.size(); ++k)
                        for (int c = 0; c < 3; ++c) ASSERT_EQ(eight.refs[k].v[c], one.refs[k].v[c]) << what << " ref " << k;
                    ASSERT_TRUE(std::ranges::equal(eight.tile_begin, one.tile_begin)) << what;
                    ASSERT_EQ(eight.covered_area.size(), one.covered_area.size()) << what;
                    for (size_t k = 0; k < one.covered_area.size(); ++k)
                        ASSERT_EQ(std::bit_cast<uint32_t>(eight.covered_area[k]), std::bit_cast<uint32_t>(one.covered_area[k])) << what << " tile " << k;
                    ASSERT_EQ(std::tie(eight.range.x0, eight.range.y0, eight.range.x1, eight.range.y1),
                              std::tie(one.range.x0, one.range.y0, one.range.x1, one.range.y1)) << what;
                    ASSERT_EQ(eight.clipped.size(), one.clipped.size()) << what;
                }
                simd::use_generic_path(false);
                // How many triangles went each way (one tile, several, none), to see the cases are met.
                std::vector<int> tiles_of(indices.size() / 3, 0);
                for (const TriangleRef& r : one.refs)
                    if (!(r.v[0] & kClippedVertex)) ++tiles_of[r.v[0] / 3];
                for (int n : tiles_of) ++kinds[n == 1 ? 0 : n > 1 ? 1 : 2];
            }
    }
    EXPECT_GT(kinds[0], 5000u);
    EXPECT_GT(kinds[1], 1000u);
    EXPECT_GT(kinds[2], 5000u);
}
