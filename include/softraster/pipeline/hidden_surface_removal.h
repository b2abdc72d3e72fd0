// Hidden-surface removal per tile, before shading (as tile-based GPUs do it).
//
// When a tile receives several opaque draws that test and write depth, most of what is
// drawn first is covered later (a stack of full-screen layers drawn back to front shades
// every pixel once per layer). For such a run of draws the tile is drawn in two passes:
//   1. visibility: rasterize every triangle, depth-test and write depth, and remember for
//      each sample which triangle wrote it last (its "owner");
//   2. shading: rasterize again and shade each pixel only for the triangle that owns some
//      of its samples, writing those samples.
// The picture is identical: with depth writes on, the last fragment to pass a sample's
// depth test is the one whose color stays there, and a triangle's color at a pixel does
// not depend on the order it is computed in. It needs shaders that never discard and
// have no side effects (PureShader, fragment_shading.h).
//
// The tile loop (Context::execute) asks hidden_surface_run which run of the tile's draws to
// draw this way; the draws' commands then call the two passes below.
#pragma once
#include <cstdint>
#include <span>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/binned_triangles.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/rasterization.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/render_state.h"

namespace softraster {

// Draw state that allows the two-pass scheme.
inline bool allows_hidden_surface_removal(const RenderState& st) {
    // (A scissor would give the draws of a run different rectangles of the tile.)
    return st.blend == BlendMode::Opaque && st.depth_test && st.depth_write && st.color_write &&
           st.depth_func != DepthFunc::Never && !st.scissor_test;
}

// A run is worth two passes when its triangles' bounds cover the tile this many times over;
// with MSAA, more times: its second pass shades one pixel at a time, where drawing each draw
// in turn shades eight at once (bench_textured_asset, docs/performance.md "The resolve and
// MSAA's two passes").
inline constexpr double kOverdrawForHiddenSurfaceRemoval = 2.5, kOverdrawForHiddenSurfaceRemovalMsaa = 8.0;

// Owner of a sample: draw (within the run) in the top 8 bits, triangle (within the draw's
// list for the tile) in the low 24.
inline constexpr uint32_t kNoOwner = 0xffffffffu;
inline uint32_t owner_id(uint32_t draw, uint32_t triangle) { return (draw << 24) | triangle; }
inline constexpr uint32_t kMaxRunDraws = 255, kMaxTileTriangles = 1u << 24;

struct HiddenSurfaceRun {
    size_t end;      // the run is draws [first, end) of the tile's list
    bool worth_it;   // draw it in two passes (else one draw after another)
};

// The longest run of the tile's draws from `first` that allow hidden-surface removal, and
// whether it is worth two passes: several draws, and enough overdraw in this tile for the
// framebuffer's sample count. `draws` are the tile's commands in draw order (pointers with
// allows_hidden_surface_removal(), triangles_in_tile(tile) and covered_area(tile)).
template <class DrawPtr>
HiddenSurfaceRun hidden_surface_run(std::span<const DrawPtr> draws, size_t first, int tile, const Rect& rect, int samples) {
    size_t end = first;
    while (end < draws.size() && end - first < kMaxRunDraws && draws[end]->allows_hidden_surface_removal() &&
           draws[end]->triangles_in_tile(tile) < kMaxTileTriangles)
        ++end;
    if (end == first) return {first + 1, false};
    if (end - first < 2) return {end, false};  // one draw: no overdraw between draws to remove
    double area = 0;
    for (size_t c = first; c < end; ++c) area += draws[c]->covered_area(tile);
    const double tile_area = double(rect.x1 - rect.x0) * double(rect.y1 - rect.y0);
    const double overdraw = samples == 1 ? kOverdrawForHiddenSurfaceRemoval : kOverdrawForHiddenSurfaceRemovalMsaa;
    return {end, area >= overdraw * tile_area};
}

// Pass 1 for one triangle: depth test and write, and `me` as the owner of every sample
// that passes. `owners` holds the tile's samples, row by row (kTileSize pixels a row,
// Samples per pixel); null for a draw that writes depth alone (a shadow map's, the tile
// back end's DepthOnly), which has no second pass. It needs the triangle's edges and depth
// only, so it is compiled once per sample count and CPU path (simd.h) for every varying count.
template <int Samples>
void visible_samples(const TriangleEdges& t, const DepthTest& test, Framebuffer& fb, const Rect& rect, uint32_t me, uint32_t* owners) {
    // Copies in locals of what the loops read after a store: a store to the depth buffer or
    // the owners may alias anything a reference reaches, which would be loaded again after
    // each. (The edges are read once, before the first store: rasterization.h.)
    const DepthPlane z_plane = t.z;
    const int origin_x = t.origin_x, origin_y = t.origin_y;
    const DepthTest depth = test;
    const int width = fb.width();
    if constexpr (Samples == 1) {  // eight pixels at a time
        using namespace simd;
        auto group_depth = [&](int x, f8 j) { return z_plane.at(to_float(kLaneIndex) + float(x - origin_x), j); };
        if (!owners) {  // depth alone (a shadow map's): no owner row to find
            rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
                float* const depth_row = fb.depth_plane() + fb.sample_index(0, y);
                const f8 j = splat(float(y - origin_y));
                for_each_group(x_begin, x_end, [&](int x, i8 covered) { depth.test_group(depth_row, x, width, group_depth(x, j), covered); });
            });
            return;
        }
        rasterize_spans(t, t.bounds, [&](int y, int x_begin, int x_end) {
            int32_t* owner = reinterpret_cast<int32_t*>(owners) + size_t(y - rect.y0) * kTileSize;  // by x - rect.x0
            float* const depth_row = fb.depth_plane() + fb.sample_index(0, y);
            const f8 j = splat(float(y - origin_y));
            for_each_group(x_begin, x_end, [&](int x, i8 covered) {
                const i8 pass = depth.test_group(depth_row, x, width, group_depth(x, j), covered);
                const int ox = x - rect.x0, ow = width - rect.x0;
                store_group(owner, ox, ow, select(pass, splat_i(int32_t(me)), load_group<i8>(owner, ox, ow)));
            });
        });
    } else {
        rasterize_triangle<Samples>(t, t.bounds, [&](const CoveredPixel<Samples>& px) {
            const unsigned pass = depth.template test_and_write_pixel<Samples>(fb.depth_plane() + fb.sample_index(px.x, px.y), px.mask, px.z.data());
            if (!owners) return;
            uint32_t* owner = owners + (size_t(px.y - rect.y0) * kTileSize + size_t(px.x - rect.x0)) * Samples;
            for (int s = 0; s < Samples; ++s)
                if (pass & (1u << s)) owner[s] = me;
        });
    }
}
template <int Samples>
[[gnu::noinline]] SOFTRASTER_AVX2_TARGET void visible_samples_wide(const TriangleEdges& t, const DepthTest& depth, Framebuffer& fb,
                                                                   const Rect& rect, uint32_t me, uint32_t* owners) {
    visible_samples<Samples>(t, depth, fb, rect, me, owners);
}
template <int Samples>
[[gnu::noinline]] void visible_samples_generic(const TriangleEdges& t, const DepthTest& depth, Framebuffer& fb, const Rect& rect,
                                               uint32_t me, uint32_t* owners) {
    visible_samples<Samples>(t, depth, fb, rect, me, owners);
}

// Pass 1 for a draw's triangles in the tile: each one's coverage and depth plane (its
// varyings' planes are not needed), then its visible samples.
template <int Samples, bool WideLanes, int N>
void visibility_pass(const BinnedTriangles<N>& triangles, const RenderState& state, Framebuffer& fb, int tx, int ty,
                     const Rect& rect, uint32_t draw, uint32_t* owners) {
    const DepthTest depth(state);
    for_each_triangle_setup<Samples, /*Planes=*/false>(triangles, state, tx, ty, rect, [&](TriangleSetup<N>& setup, uint32_t id) {
        setup_depth_plane(setup, plane_basis(setup));
        if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) visible_samples_wide<Samples>(setup, depth, fb, rect, owner_id(draw, id), owners);
        else visible_samples_generic<Samples>(setup, depth, fb, rect, owner_id(draw, id), owners);
    });
}

// Pass 2: shade each pixel for the triangle that owns some of its samples, and write those.
// Returns the fragments shaded. Compiled per varying layout (shader_layout.h).
template <int Samples, class L, bool WideLanes>
uint64_t shading_pass(const LayoutShader<L>& shader, const BinnedTriangles<L::N>& triangles, const RenderState& state, Framebuffer& fb,
                      int tx, int ty, const Rect& rect, uint32_t draw, const uint32_t* owners) {
    constexpr int N = L::N;
    const FragmentCalls<N>& calls = shader.code->path(WideLanes);
    const int width = fb.width();
    const BlendSettings blend(state, fb.color_space());
    uint64_t shaded = 0;
    static thread_local PendingGroups<N> groups;  // (off the stack, as in tile_back_end.h)
    for_each_triangle_setup<Samples, true, L::kFlat>(triangles, state, tx, ty, rect, [&](const TriangleSetup<N>& setup, uint32_t id) {
        const uint32_t me = owner_id(draw, id);
        if constexpr (Samples == 1 && L::kBatch) {  // eight pixels at a time, a batch of groups a call
            using namespace simd;
            groups.start(setup.front_facing);
            rasterize_spans(setup, setup.bounds, [&](int y, int x_begin, int x_end) {
                const int32_t* owner = reinterpret_cast<const int32_t*>(owners) + size_t(y - rect.y0) * kTileSize;  // by x - rect.x0
                const f8 j = splat(float(y - setup.origin_y));
                for_each_group(x_begin, x_end, [&](int x, i8 lanes) {
                    const i8 mine = lanes & (load_group<i8>(owner, x - rect.x0, width - rect.x0) == int32_t(me));
                    if (!any(mine)) return;
                    const f8 i = to_float(kLaneIndex) + float(x - setup.origin_x);
                    shaded += unsigned(__builtin_popcount(bits(mine)));
                    groups.add(y, x, mine, interpolate_depth(setup, i, j)) = interpolate_varyings<L>(setup, i, j);
                    if (groups.full()) shade_and_merge<WideLanes>(calls.groups, shader.self, blend, fb, groups);
                });
            });
            shade_and_merge<WideLanes>(calls.groups, shader.self, blend, fb, groups);
        } else {
            rasterize_triangle<Samples>(setup, setup.bounds, [&](const CoveredPixel<Samples>& px) {
                const uint32_t* owner = owners + (size_t(px.y - rect.y0) * kTileSize + size_t(px.x - rect.x0)) * Samples;
                unsigned mine = 0;
                for (int s = 0; s < Samples; ++s)
                    if ((px.mask & (1u << s)) && owner[s] == me) mine |= 1u << s;
                if (!mine) return;
                const float i = float(px.x - setup.origin_x), j = float(px.y - setup.origin_y);
                glm::vec4 color;
                calls.pixel(shader.self, interpolate_varyings<L>(setup, i, j),
                            FragCoord{float(px.x) + 0.5f, float(px.y) + 0.5f, interpolate_depth(setup, i, j), setup.front_facing}, color);
                ++shaded;
                merge_fragment<Samples, /*Blended=*/false>(blend, fb.color_plane() + fb.sample_index(px.x, px.y), mine, color);
            });
        }
    });
    return shaded;
}

}  // namespace softraster
