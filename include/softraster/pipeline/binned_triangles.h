// A draw's triangles in one tile: what binning (binning.h) left for the tile back ends, and
// the walk over them in draw order with each one's triangle setup (triangle_setup.h). Every
// back end (tile_back_end.h, hidden_surface_removal.h, general_back_end.h) starts here.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>

#include "softraster/pipeline/binning.h"
#include "softraster/pipeline/triangle_setup.h"
#include "softraster/render_state.h"

namespace softraster {

// A draw's triangles as binning left them: its chunks' bins and its post-transform vertices.
template <int N>
struct BinnedTriangles {
    std::span<const TriangleBin<N>> bins;
    const ShadedVertex<N>* post = nullptr;
};

// Calls f(setup, ordinal) for each of the draw's triangles in tile (tx, ty), whose pixels
// are `rect`, in draw order; the ordinal counts them (hidden_surface_removal.h names a
// triangle by it). Without Planes, the setup has its coverage only (f makes the planes
// when it needs them). With Constant, the planes look for constant varyings if
// find_constant (setup_planes).
template <int Samples, bool Planes = true, uint64_t Flat = 0, bool Constant = false, int N, class F>
void for_each_triangle_setup(const BinnedTriangles<N>& draw, const RenderState& state, int tx, int ty, const Rect& rect, F&& f,
                             bool find_constant = false) {
    TriangleSetup<N> setup;
    setup.options = PlaneOptions::of(state);
    setup.options.find_constant = Constant && find_constant;
    const FrontFace front = state.front_face;
    uint32_t ordinal = 0;
    // Setup reads the window position and varyings of three vertices anywhere in the
    // draw's vertex buffer: fetch those of a triangle a few places ahead into the cache
    // while this one is drawn, or the loads wait on memory.
    constexpr size_t kAhead = 4;
    for (const TriangleBin<N>& bin : draw.bins) {
        const std::span<const TriangleRef> refs = bin.triangles_in(tx, ty);
        // (Only vertices of the post-transform buffer: the few the clipper made sit in a
        // short list of their own. GCC 12 drops a prefetch whose address is chosen by a
        // condition, as bin.vertex() chooses between the two lists.)
        auto prefetch = [&](const TriangleRef& r) {
            for (uint32_t i : r.v) {
                if (i & kClippedVertex) continue;
                const char* v = reinterpret_cast<const char*>(draw.post + i);
                __builtin_prefetch(v);  // at most two cache lines
                __builtin_prefetch(v + sizeof(ShadedVertex<N>) - 1);
            }
        };
        for (size_t a = 1; a < std::min(refs.size(), kAhead); ++a) prefetch(refs[a]);
        for (size_t k = 0; k < refs.size(); ++k, ++ordinal) {
            if (k + kAhead < refs.size()) prefetch(refs[k + kAhead]);
            const TriangleRef& r = refs[k];
            if (setup_coverage<Samples>(bin.vertex(r.v[0], draw.post), bin.vertex(r.v[1], draw.post),
                                        bin.vertex(r.v[2], draw.post), front, rect, setup)) {
                if constexpr (Planes) setup_planes<Flat, Constant>(setup);
                f(setup, ordinal);
            }
        }
    }
}

}  // namespace softraster
