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
// have no side effects, which a shader states with `static constexpr bool kPure = true;`.
#pragma once
#include <cstdint>

#include "softraster/pipeline/shader.h"
#include "softraster/render_state.h"

namespace softraster {

template <class S>
concept PureShader = requires { requires S::kPure; };

// Draw state that allows the two-pass scheme.
inline bool allows_hidden_surface_removal(const RenderState& st) {
    return st.blend == BlendMode::Opaque && st.depth_test && st.depth_write && st.color_write &&
           st.depth_func != DepthFunc::Never;
}

// A run is worth two passes when its triangles' boxes cover the tile this many times over.
inline constexpr double kOverdrawForHiddenSurfaceRemoval = 2.5;

// Owner of a sample: draw (within the run) in the top 8 bits, triangle (within the draw's
// list for the tile) in the low 24.
inline constexpr uint32_t kNoOwner = 0xffffffffu;
inline uint32_t owner_id(uint32_t draw, uint32_t triangle) { return (draw << 24) | triangle; }
inline constexpr uint32_t kMaxRunDraws = 255, kMaxTileTriangles = 1u << 24;

}  // namespace softraster
