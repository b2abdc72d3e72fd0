// The shader as the back end sees it: a varying layout, and fragment code behind
// out-of-line calls.
//
// The tile loops (tile_back_end.h, hidden_surface_removal.h, general_back_end.h) depend on a
// shader only through its varyings: how many there are, which are flat, where a texture's
// coordinate derivatives go, and which batch entry points the shader has. That is its
// VaryingLayout. The loops are compiled once per layout (the scene's 32 surface shaders
// have 14), and call the shader's fragment code
// through a table of function pointers chosen when the draw is recorded (FragmentCode).
// Each call shades a batch, never one group alone: up to two rows of a triangle's span
// (FragmentGroups), one flush of the fragment queue, or one pixel on the scalar paths that
// also run the shader one pixel at a time. So the build grows with layouts, not shaders,
// and the call's cost is spread over many fragments (docs/performance.md, "Build time").
#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

// What the loops know of a shader at compile time. (It also serves as the shader type for
// interpolation.h, which reads kFlat, kDerivativeOf and kDerivativeAt.)
template <int Count, uint64_t FlatBits, int DerivativeOf, int DerivativeAt, bool Pure, bool Batch, bool QuadRows>
struct VaryingLayout {
    static constexpr int N = Count;
    static constexpr uint64_t kFlat = FlatBits;
    static constexpr int kDerivativeOf = DerivativeOf, kDerivativeAt = DerivativeAt;
    static constexpr bool kPure = Pure;                  // PureShader
    static constexpr bool kBatch = Batch;                // has fragment_batch (BatchShader)
    static constexpr bool kQuadRows = QuadRows;          // has fragment_pair and derivatives: quad rows go in pairs
};

template <class S>
inline constexpr int kDerivativeOfShader = [] {
    if constexpr (DerivativeShader<S>) return int(S::kDerivativeOf);
    else return -1;
}();
template <class S>
inline constexpr int kDerivativeAtShader = [] {
    if constexpr (DerivativeShader<S>) return int(S::kDerivativeAt);
    else return -1;
}();

template <Shader S>
using LayoutOf = VaryingLayout<kVaryingCount<typename S::Varyings>, kFlatVaryings<S>, kDerivativeOfShader<S>, kDerivativeAtShader<S>,
                               PureShader<S>, BatchShader<S>, PairShader<S> && DerivativeShader<S>>;

// Groups of eight fragments to shade with one call: each group's window depths, first
// pixel (x, y) and varyings in, its colors out. In a batch of quad-row pairs, groups 2k and
// 2k + 1 are the two rows of a row of 2x2 quads. (All but the varyings in a base of their
// own, the same for every varying count: the merge that follows is compiled once.)
struct GroupPlaces {
    static constexpr int kCapacity = 16;  // two rows of a 64-pixel tile
    int count = 0;
    bool front_facing = true;
    int x[kCapacity], y[kCapacity];
    simd::f8 z[kCapacity];
    std::array<simd::f8, 4> rgba[kCapacity];
};
template <int N>
struct FragmentGroups : GroupPlaces {
    std::array<simd::f8, size_t(N)> varyings[kCapacity];
};

// One CPU path's copies of a shader's fragment code.
template <int N>
struct FragmentCalls {
    void (*groups)(const void* shader, FragmentGroups<N>& batch) = nullptr;     // fragment_batch per group
    void (*quad_rows)(const void* shader, FragmentGroups<N>& batch) = nullptr;  // per pair (or two side by side)
    bool (*pixel)(const void* shader, const std::array<float, size_t(N)>& varyings, const FragCoord& frag, glm::vec4& color) = nullptr;
};
template <int N>
struct FragmentCode {
    FragmentCalls<N> wide, generic;  // compiled for AVX2 (simd.h, on_best_path), and for any x86-64
    // The color depends on the varyings alone (VaryingsOnlyShader): a value, not part of the
    // layout, since it only lets blended draws shade a triangle of constant varyings once
    // (tile_back_end.h), and a copy of the loops per value would cost a back end's build.
    bool varyings_only = false;
    const FragmentCalls<N>& path(bool wide_lanes) const { return wide_lanes ? wide : generic; }
};

// The shader of layout L as the loops call it: the shader object and its code.
template <class L>
struct LayoutShader {
    static constexpr int N = L::N;
    const void* self = nullptr;
    const FragmentCode<N>* code = nullptr;
};

// ---- a shader's fragment code, compiled once per shader and CPU path

namespace fragment_code {
// Groups g to g + 3 of the batch with one call (FourShader).
template <class S, int N>
inline void four_groups(const S& shader, FragmentGroups<N>& b, size_t g) {
    const std::array<simd::f8, size_t(N)>(&v)[4] = *reinterpret_cast<const std::array<simd::f8, size_t(N)>(*)[4]>(&b.varyings[g]);
    const simd::f8(&z)[4] = *reinterpret_cast<const simd::f8(*)[4]>(&b.z[g]);
    std::array<simd::f8, 4>(&rgba)[4] = *reinterpret_cast<std::array<simd::f8, 4>(*)[4]>(&b.rgba[g]);
    shader.fragment_four(v, z, b.front_facing, rgba);
}
// The groups four or two at a time where the shader takes them (FourShader, PairShader):
// any groups, each with its own derivatives (the fragment queue's hold pixels of
// neighbouring small triangles), whose texture lookups then overlap.
template <class S, int N>
inline void groups(const S& shader, FragmentGroups<N>& b) {
    if constexpr (PairShader<S>) {
        int g = 0;
        if constexpr (FourShader<S>)
            for (; g + 3 < b.count; g += 4) four_groups(shader, b, size_t(g));
        for (; g + 1 < b.count; g += 2) shader.fragment_pair(b.varyings[g], b.varyings[g + 1], b.z[g], b.z[g + 1], b.front_facing, b.rgba[g], b.rgba[g + 1]);
        if (g < b.count) shader.fragment_batch(b.varyings[g], b.z[g], b.front_facing, b.rgba[g]);
    } else if constexpr (requires { shader.batch_constants(); }) {  // what every group uses, read once
        const auto k = shader.batch_constants();
        for (int g = 0; g < b.count; ++g) shader.fragment_batch(k, b.varyings[g], b.z[g], b.front_facing, b.rgba[g]);
    } else {
        for (int g = 0; g < b.count; ++g) shader.fragment_batch(b.varyings[g], b.z[g], b.front_facing, b.rgba[g]);
    }
}
// Pairs side by side (x eight apart) go four groups at a time where the shader takes four
// (FourShader), else each pair alone.
template <class S, int N>
inline void quad_rows(const S& shader, FragmentGroups<N>& b) {
    const int pairs = b.count / 2;
    for (int k = 0; k < pairs; ++k) {
        const size_t g = size_t(2 * k);
        if constexpr (FourShader<S>) {
            if (k + 1 < pairs && b.x[g + 2] == b.x[g] + simd::kLanes && b.y[g + 2] == b.y[g]) {
                four_groups(shader, b, g);
                ++k;
                continue;
            }
        }
        shader.fragment_pair(b.varyings[g], b.varyings[g + 1], b.z[g], b.z[g + 1], b.front_facing, b.rgba[g], b.rgba[g + 1]);
    }
}
template <class S, int N>
inline bool pixel(const S& shader, const std::array<float, size_t(N)>& v, const FragCoord& frag, glm::vec4& color) {
    return shader.fragment(from_array<typename S::Varyings>(v), frag, color);
}

// The entry points: the AVX2 copies flattened like the back ends' (simd.h).
template <class S, int N>
SOFTRASTER_AVX2_TARGET void groups_wide(const void* s, FragmentGroups<N>& b) { groups(*static_cast<const S*>(s), b); }
template <class S, int N>
void groups_generic(const void* s, FragmentGroups<N>& b) { groups(*static_cast<const S*>(s), b); }
template <class S, int N>
SOFTRASTER_AVX2_TARGET void quad_rows_wide(const void* s, FragmentGroups<N>& b) { quad_rows(*static_cast<const S*>(s), b); }
template <class S, int N>
void quad_rows_generic(const void* s, FragmentGroups<N>& b) { quad_rows(*static_cast<const S*>(s), b); }
template <class S, int N>
SOFTRASTER_AVX2_TARGET bool pixel_wide(const void* s, const std::array<float, size_t(N)>& v, const FragCoord& f, glm::vec4& c) {
    return pixel<S, N>(*static_cast<const S*>(s), v, f, c);
}
template <class S, int N>
bool pixel_generic(const void* s, const std::array<float, size_t(N)>& v, const FragCoord& f, glm::vec4& c) {
    return pixel<S, N>(*static_cast<const S*>(s), v, f, c);
}

template <class S, bool Wide>
constexpr FragmentCalls<kVaryingCount<typename S::Varyings>> calls() {
    constexpr int N = kVaryingCount<typename S::Varyings>;
    FragmentCalls<N> c;
    if constexpr (Wide && SOFTRASTER_HAS_AVX2_PATH) {
        c.pixel = &pixel_wide<S, N>;
        if constexpr (BatchShader<S>) c.groups = &groups_wide<S, N>;
        if constexpr (LayoutOf<S>::kQuadRows) c.quad_rows = &quad_rows_wide<S, N>;
    } else {
        c.pixel = &pixel_generic<S, N>;
        if constexpr (BatchShader<S>) c.groups = &groups_generic<S, N>;
        if constexpr (LayoutOf<S>::kQuadRows) c.quad_rows = &quad_rows_generic<S, N>;
    }
    return c;
}
}  // namespace fragment_code

// Shader S's fragment code, one table per shader type (the functions are compiled where
// the draw is recorded: with the shader, not with the loops).
template <Shader S>
inline constexpr FragmentCode<kVaryingCount<typename S::Varyings>> kFragmentCode{fragment_code::calls<S, true>(),
                                                                                  fragment_code::calls<S, false>(),
                                                                                  VaryingsOnlyShader<S>};

template <Shader S>
LayoutShader<LayoutOf<S>> layout_shader(const S& shader) {
    return {&shader, &kFragmentCode<S>};
}

}  // namespace softraster
