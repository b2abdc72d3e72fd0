// Stage 11, fragment shading: the user's fragment shader, for one pixel or for groups of eight.
//
// With MSAA the shader runs once per pixel, at the pixel center, and its color goes to every
// covered sample that passed the depth test. A shader may also offer fragment_batch (the
// same formulas on eight pixels at once, BatchShader in shader.h); the back end then shades
// groups of eight pixels of a row, or eight queued fragments (fragment_queue.h).
//
// The back ends reach the shader through its layout (shader_layout.h): out-of-line calls
// that each shade a batch. So every strategy of the tile back end runs the same sequence
// for a triangle: rasterize -> early depth (and stencil) test per group -> the groups that
// pass wait in PendingGroups -> one call shades them -> each is merged into its row
// (output_merge.h). A pixel drawn once per triangle makes the order among a triangle's
// groups irrelevant; the batch is shaded and merged before the next triangle draws.
#pragma once
#include <array>
#include <cstdint>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/depth_stencil.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

// Groups of a triangle that passed their tests and wait for their colors: the shader's
// batch (varyings, depths, places) and, per group, the lanes to write.
template <int N>
struct PendingGroups {
    static constexpr int kCapacity = GroupPlaces::kCapacity;
    FragmentGroups<N> batch;
    std::array<simd::i8, kCapacity> pass;

    void start(bool front_facing) {
        batch.count = 0;
        batch.front_facing = front_facing;
    }
    bool empty() const { return batch.count == 0; }
    bool full() const { return batch.count == kCapacity; }
    // Adds a group and returns the slot for its varyings.
    std::array<simd::f8, size_t(N)>& add(int row, int x, simd::i8 lanes, simd::f8 z) {
        const size_t g = size_t(batch.count++);
        batch.y[g] = row, batch.x[g] = x, pass[g] = lanes, batch.z[g] = z;
        return batch.varyings[g];
    }
};

// Merges each group's colors into its row, the lanes `pass`: blend_group, or for Custom
// blending each row's run of groups together (blend_row). The same for every layout, so
// compiled once (src/pipeline/output_merge.cpp) in each CPU path's copy (simd.h), and
// called once per batch.
template <bool Blended>
SOFTRASTER_AVX2_TARGET void merge_groups_wide(const BlendSettings& blend, Framebuffer& fb, const GroupPlaces& p, const simd::i8* pass);
template <bool Blended>
void merge_groups_generic(const BlendSettings& blend, Framebuffer& fb, const GroupPlaces& p, const simd::i8* pass);

// Shades the pending groups with one call (`shade`: the layout's groups or quad_rows entry),
// then merges them (the opaque or the blending merge, chosen once per batch) and empties
// the list.
template <bool WideLanes, int N>
inline void shade_and_merge(void (*shade)(const void*, FragmentGroups<N>&), const void* shader, const BlendSettings& blend, Framebuffer& fb,
                            PendingGroups<N>& p) {
    if (p.empty()) return;
    shade(shader, p.batch);
    if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) {
        if (blend.blends()) merge_groups_wide<true>(blend, fb, p.batch, p.pass.data());
        else merge_groups_wide<false>(blend, fb, p.batch, p.pass.data());
    } else {
        if (blend.blends()) merge_groups_generic<true>(blend, fb, p.batch, p.pass.data());
        else merge_groups_generic<false>(blend, fb, p.batch, p.pass.data());
    }
    p.batch.count = 0;
}

// One fragment of pixel (x, y) whose samples `covered` lie at depths z: the depth test
// (depth_stencil.h), the shader with the varyings make_varyings() returns, then the depth
// write and the output merge for the samples that passed, unless the shader discarded.
template <int Samples, class DepthStencil, int N, class MakeVaryings>
inline void shade_fragment(const FragmentCalls<N>& calls, const void* shader, const DepthStencil& depth, const BlendSettings& blend,
                           Framebuffer& fb, int x, int y, unsigned covered, const float* z, float center_z, bool front_facing,
                           MakeVaryings&& make_varyings, uint64_t& shaded) {
    const size_t base = fb.sample_index(x, y);
    const unsigned pass = depth.template test_pixel<Samples>(fb.depth_plane() + base, covered, z);
    if (!pass) return;
    ++shaded;
    const FragCoord frag{float(x) + 0.5f, float(y) + 0.5f, center_z, front_facing};
    glm::vec4 color;
    if (!calls.pixel(shader, make_varyings(), frag, color)) return;
    depth.template write_pixel<Samples>(fb.depth_plane() + base, pass, z);
    if (!blend.color_mask) return;
    if (blend.blends()) merge_fragment<Samples, true>(blend, fb.color_plane() + base, pass, color);
    else merge_fragment<Samples, false>(blend, fb.color_plane() + base, pass, color);
}

}  // namespace softraster
