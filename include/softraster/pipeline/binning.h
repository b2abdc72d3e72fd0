// Primitive assembly, clipping, culling and binning: the front end's triangle half.
//
// Following Mesa llvmpipe (lp_setup -> lp_scene -> lp_rast): the picture is cut into 64x64
// tiles; each triangle that survives clipping and culling is appended to the bin of every
// tile its bounding box touches (the pixels with a sample in the box). Later one thread at
// a time owns a tile and draws its bin in draw order, so no two threads ever write the same
// pixel and no locks are needed.
//
// The triangles of a draw are binned in chunks, in parallel; each chunk groups its
// triangles by tile (a counting sort), keeping their order, so walking the chunks in order
// and, in each, the tile's slice gives the tile's triangles in draw order.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/culling.h"
#include "softraster/pipeline/primitive_assembly.h"
#include "softraster/pipeline/triangle_setup.h"
#include "softraster/pipeline/vertex_processing.h"

namespace softraster {

inline constexpr int kTileSize = 64;  // pixels, as llvmpipe

struct TileGrid {
    int width = 0, height = 0, tiles_x = 0, tiles_y = 0;
    TileGrid() = default;
    TileGrid(int w, int h) : width(w), height(h), tiles_x((w + kTileSize - 1) / kTileSize), tiles_y((h + kTileSize - 1) / kTileSize) {}
    int count() const { return tiles_x * tiles_y; }
    Rect tile_rect(int t) const {
        const int x = (t % tiles_x) * kTileSize, y = (t / tiles_x) * kTileSize;
        return {x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)};
    }
};

// A binned triangle: its corners in the draw's post-transform buffer or, flagged with
// kClippedVertex, in its chunk's clipper output.
inline constexpr uint32_t kClippedVertex = 0x80000000u;
struct TriangleRef {
    uint32_t v[3];
};

template <int N>
struct TriangleBin {
    std::vector<ShadedVertex<N>> clipped;  // vertices the clipper made
    std::vector<TriangleRef> refs;         // grouped by tile, draw order within each tile
    std::vector<uint32_t> tile_begin;      // tile t's refs: [tile_begin[t], tile_begin[t + 1])
    std::vector<std::pair<uint32_t, TriangleRef>> pending;  // (tile, triangle) before grouping
    // Per tile: the pixels its triangles cover, summed (each triangle's area, at most its
    // bounding box within the tile), an estimate of the overdraw (hidden_surface_removal.h).
    std::vector<float> covered_area;

    const ShadedVertex<N>& vertex(uint32_t i, const ShadedVertex<N>* post) const {
        return (i & kClippedVertex) ? clipped[i & ~kClippedVertex] : post[i];
    }
};

struct FaceState {
    CullMode cull = CullMode::Back;
    FrontFace front = FrontFace::CCW;
};

// Assembles, clips, culls and bins the triangles of `indices` (three per triangle), for a
// framebuffer of `Samples` samples per pixel: a triangle whose bounding box holds no sample
// is dropped here (triangle_setup.h, pixel_bounds).
template <int Samples, int N>
void bin_triangles(std::span<const uint32_t> indices, const ShadedVertex<N>* post, const ClipPlanes& planes,
                   const Viewport& vp, FaceState faces, const TileGrid& grid, TriangleBin<N>& bin) {
    bin.clipped.clear();
    bin.pending.clear();
    bin.covered_area.assign(size_t(grid.count()), 0.0f);
    const Rect screen{0, 0, grid.width, grid.height};
    auto emit = [&](uint32_t ia, uint32_t ib, uint32_t ic) {
        const ShadedVertex<N>& a = bin.vertex(ia, post);
        const ShadedVertex<N>& b = bin.vertex(ib, post);
        const ShadedVertex<N>& c = bin.vertex(ic, post);
        const int64_t area2 = signed_area2(a.X, a.Y, b.X, b.Y, c.X, c.Y);
        if (area2 == 0) return;  // zero snapped area: never drawn
        if (is_culled(is_front_facing(area2 < 0, faces.front), faces.cull)) return;
        const Rect r = pixel_bounds<Samples>(a, b, c);
        const int x0 = std::max(r.x0, screen.x0), y0 = std::max(r.y0, screen.y0);
        const int x1 = std::min(r.x1, screen.x1), y1 = std::min(r.y1, screen.y1);
        if (x0 >= x1 || y0 >= y1) return;
        const float area = float(std::abs(area2)) * (0.5f / float(kSubpixelOne * kSubpixelOne));
        for (int ty = y0 / kTileSize; ty <= (y1 - 1) / kTileSize; ++ty)
            for (int tx = x0 / kTileSize; tx <= (x1 - 1) / kTileSize; ++tx) {
                const uint32_t tile = uint32_t(ty * grid.tiles_x + tx);
                bin.pending.push_back({tile, TriangleRef{{ia, ib, ic}}});
                const int w = std::min(x1, (tx + 1) * kTileSize) - std::max(x0, tx * kTileSize);
                const int h = std::min(y1, (ty + 1) * kTileSize) - std::max(y0, ty * kTileSize);
                bin.covered_area[tile] += std::min(float(w * h), area);
            }
    };
    ClipPolygon<N> poly;
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const uint32_t ia = indices[i], ib = indices[i + 1], ic = indices[i + 2];
        const ShadedVertex<N>& a = post[ia];
        const ShadedVertex<N>& b = post[ib];
        const ShadedVertex<N>& c = post[ic];
        if (!a.finite || !b.finite || !c.finite) continue;  // NaN or infinite position
        if (a.outcode & b.outcode & c.outcode) continue;     // all outside one plane
        const unsigned mask = a.outcode | b.outcode | c.outcode;
        if (mask == 0) {
            emit(ia, ib, ic);
            continue;
        }
        const int n = clip_triangle(a.clip, b.clip, c.clip, planes, mask, poly);
        const auto first = uint32_t(bin.clipped.size());
        int mapped = 0;
        for (int k = 0; k < n; ++k) {
            ShadedVertex<N> v;
            if (!finish_vertex(poly.v[size_t(k)], vp, v)) break;
            bin.clipped.push_back(v);
            ++mapped;
        }
        if (mapped != n) {
            bin.clipped.resize(first);
            continue;
        }
        for (int k = 1; k + 1 < n; ++k)  // fan (0, k, k+1)
            emit(first | kClippedVertex, (first + uint32_t(k)) | kClippedVertex, (first + uint32_t(k) + 1) | kClippedVertex);
    }

    // Group by tile, keeping order (counting sort).
    bin.tile_begin.assign(size_t(grid.count()) + 1, 0);
    for (const auto& p : bin.pending) ++bin.tile_begin[p.first + 1];
    for (size_t t = 1; t < bin.tile_begin.size(); ++t) bin.tile_begin[t] += bin.tile_begin[t - 1];
    bin.refs.resize(bin.pending.size());
    std::vector<uint32_t>& cursor = bin.tile_begin;  // reuse: advance each start, then shift back
    for (const auto& p : bin.pending) bin.refs[cursor[p.first]++] = p.second;
    for (size_t t = bin.tile_begin.size() - 1; t > 0; --t) bin.tile_begin[t] = bin.tile_begin[t - 1];
    bin.tile_begin[0] = 0;
}

}  // namespace softraster
