// Binning: the front end's last stage. Each triangle that survives clipping and culling is
// appended to the bin of every tile its bounds touch (the pixels with a sample in its box,
// sample_pattern.h), so that later each tile is drawn by one thread from its own list.
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
#include <cstdint>
#include <span>
#include <vector>

#include "softraster/pipeline/culling.h"
#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/primitive_assembly.h"
#include "softraster/pipeline/sample_pattern.h"
#include "softraster/pipeline/vertex_processing.h"

namespace softraster {

// A binned triangle: its corners (primitive_assembly.h, corner_vertex).
struct TriangleRef {
    uint32_t v[3];
};

template <int N>
struct TriangleBin {
    std::vector<ShadedVertex<N>> clipped;  // vertices the clipper made
    TileRange range;                       // the tiles this chunk's triangles touch
    std::vector<TriangleRef> refs;         // grouped by tile of `range`, draw order within each
    std::vector<uint32_t> tile_begin;      // local tile k's refs: [tile_begin[k], tile_begin[k + 1])
    // Per local tile: the pixels its triangles cover, summed (each triangle's area, at most
    // its bounds within the tile), an estimate of the overdraw (hidden_surface_removal.h).
    std::vector<float> covered_area;

    struct Pending {  // a (tile, triangle) pair before grouping
        uint16_t tx, ty;
        float area;
        TriangleRef ref;
    };
    std::vector<Pending> pending;

    const ShadedVertex<N>& vertex(uint32_t i, const ShadedVertex<N>* post) const { return corner_vertex(i, post, clipped); }
    // The chunk's triangles in tile (tx, ty), in draw order.
    std::span<const TriangleRef> triangles_in(int tx, int ty) const {
        const int k = range.local(tx, ty);
        if (k < 0) return {};
        return std::span<const TriangleRef>(refs).subspan(tile_begin[size_t(k)], tile_begin[size_t(k) + 1] - tile_begin[size_t(k)]);
    }
};

// Appends triangle `ref`, whose samples may lie in pixels `bounds` and whose snapped area is
// |area2| / 2 in 1/256-pixel units squared, to every tile of `grid` the bounds touch.
template <int N>
void add_to_tiles(TriangleBin<N>& bin, const TileGrid& grid, TriangleRef ref, Rect bounds, int64_t area2) {
    const Rect r = intersect(bounds, Rect{0, 0, grid.width, grid.height});
    if (r.empty()) return;
    const float area = float(area2 < 0 ? -area2 : area2) * (0.5f / float(kSubpixelOne * kSubpixelOne));
    const int tx0 = r.x0 / kTileSize, tx1 = (r.x1 - 1) / kTileSize, ty0 = r.y0 / kTileSize, ty1 = (r.y1 - 1) / kTileSize;
    bin.range.include(tx0, ty0);
    bin.range.include(tx1, ty1);
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const int w = std::min(r.x1, (tx + 1) * kTileSize) - std::max(r.x0, tx * kTileSize);
            const int h = std::min(r.y1, (ty + 1) * kTileSize) - std::max(r.y0, ty * kTileSize);
            bin.pending.push_back({uint16_t(tx), uint16_t(ty), std::min(float(w * h), area), ref});
        }
}

// Groups the pending triangles by tile, keeping their order (a counting sort over the
// chunk's range of tiles).
template <int N>
void group_by_tile(TriangleBin<N>& bin) {
    const size_t tiles = size_t(bin.range.count());
    bin.tile_begin.assign(tiles + 1, 0);
    bin.covered_area.assign(tiles, 0.0f);
    // Every pending tile lies in the range: its index there needs no check.
    const TileRange& r = bin.range;
    auto local = [&](const auto& p) { return size_t((p.ty - r.y0) * r.width() + (p.tx - r.x0)); };
    for (const auto& p : bin.pending) {
        const size_t k = local(p);
        ++bin.tile_begin[k + 1];
        bin.covered_area[k] += p.area;
    }
    for (size_t k = 1; k <= tiles; ++k) bin.tile_begin[k] += bin.tile_begin[k - 1];
    bin.refs.resize(bin.pending.size());
    std::vector<uint32_t>& cursor = bin.tile_begin;  // reuse: advance each start, then shift back
    for (const auto& p : bin.pending) bin.refs[cursor[local(p)]++] = p.ref;
    for (size_t k = tiles; k > 0; --k) bin.tile_begin[k] = bin.tile_begin[k - 1];
    bin.tile_begin[0] = 0;
}

// The front end's triangle half for one chunk of a draw, stage by stage: primitive assembly
// and clipping (primitive_assembly.h), culling (culling.h), binning. For a framebuffer of
// `Samples` samples per pixel: a triangle whose bounds hold no sample is dropped.
template <int Samples, int N>
void bin_triangles(std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipPlanes& planes,
                   const Viewport& vp, FaceState faces, FlatVaryings flat, const TileGrid& grid, TriangleBin<N>& bin) {
    bin.clipped.clear();
    bin.pending.clear();
    bin.range = {};
    assemble_triangles(indices, post, planes, vp, flat, bin.clipped, [&](uint32_t ia, uint32_t ib, uint32_t ic) {
        const ShadedVertex<N>&a = bin.vertex(ia, post), &b = bin.vertex(ib, post), &c = bin.vertex(ic, post);
        const int64_t area2 = signed_area2(a.X, a.Y, b.X, b.Y, c.X, c.Y);
        if (!survives_culling(area2, faces)) return;
        add_to_tiles(bin, grid, TriangleRef{{ia, ib, ic}}, pixel_bounds<Samples>(a, b, c), area2);
    });
    group_by_tile(bin);
}

}  // namespace softraster
