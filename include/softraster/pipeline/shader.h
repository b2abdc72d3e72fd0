// What a user's shader looks like. A shader is a plain struct, passed to draws as a template
// argument, so the per-vertex and per-fragment calls are direct (and inlined), never virtual.
//
//   struct MyShader {
//       using Vertex = MyVertex;       // one element of the vertex buffer
//       using Varyings = MyVaryings;   // a struct of floats, interpolated across primitives
//       glm::vec4 vertex(const Vertex& in, Varyings& out) const;          // clip-space position
//       bool fragment(const Varyings& in, const FragCoord& frag, glm::vec4& color) const;
//   };                                                                   // false = discard
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <concepts>
#include <cstring>
#include <type_traits>

#include <glm/vec4.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

// The built-in fragment inputs (gl_FragCoord, gl_FrontFacing): window position of the
// pixel center (row 0 at the top), window depth there, and the facing of the primitive.
struct FragCoord {
    float x = 0, y = 0, z = 0;
    bool front_facing = true;
};

// Varyings are any trivially copyable struct made only of floats (glm vectors count).
template <class V>
concept VaryingStruct = std::is_trivially_copyable_v<V> && std::is_default_constructible_v<V> &&
                        sizeof(V) % sizeof(float) == 0 && alignof(V) <= alignof(float);

template <class V>
inline constexpr int kVaryingCount = int(sizeof(V) / sizeof(float));

// Varyings travel through clipping and setup as flat float arrays; these convert.
template <VaryingStruct V>
using VaryingArray = std::array<float, kVaryingCount<V>>;

template <VaryingStruct V>
inline VaryingArray<V> to_array(const V& v) {
    VaryingArray<V> a;
    std::memcpy(a.data(), &v, sizeof(V));
    return a;
}

template <VaryingStruct V>
inline V from_array(const VaryingArray<V>& a) {
    V v;
    std::memcpy(&v, a.data(), sizeof(V));
    return v;
}

// Flat varyings (GLSL's `flat`): a shader may declare
//     static constexpr uint64_t kFlat = varying_bits(offsetof(MyVaryings, color), sizeof(glm::vec3));
// and those floats are not interpolated: every fragment of a primitive gets the values of
// its provoking vertex (RenderState::provoking_vertex), as written by the vertex shader.
constexpr uint64_t varying_bits(size_t byte_offset, size_t byte_size) {
    uint64_t bits = 0;
    for (size_t k = byte_offset / sizeof(float); k < (byte_offset + byte_size) / sizeof(float); ++k) bits |= uint64_t(1) << k;
    return bits;
}
template <class S>
inline constexpr uint64_t kFlatVaryings = [] {
    if constexpr (requires { S::kFlat; }) return uint64_t(S::kFlat);
    else return uint64_t(0);
}();

// Screen-space derivatives (GLSL's dFdx and dFdy, coarse: one value per 2x2 quad of pixels,
// as llvmpipe computes them for texture lookups). A shader declares
//     static constexpr int kDerivativeOf = <index of the first float of a 2-float varying>;
//     static constexpr int kDerivativeAt = <index of 4 more floats: both d/dx, then both d/dy>;
// with those 4 floats among its flat varyings (kFlat), left 0 by the vertex shader:
// interpolation (interpolate_varyings in interpolation.h) fills them at each pixel.
// (kDerivativeOf = -1: none.)
template <class S>
concept DerivativeShader = requires {
    requires S::kDerivativeOf >= 0;
    S::kDerivativeAt;
};

// A shader whose color depends on its varyings alone (not on the fragment's position, depth
// or facing) says so with `static constexpr bool kVaryingsOnly = true;`: a triangle whose
// varyings are constant (triangle_setup.h) is then shaded once, not once per pixel.
template <class S>
concept VaryingsOnlyShader = requires { requires S::kVaryingsOnly; };

template <class S>
concept Shader = VaryingStruct<typename S::Varyings> &&
    requires(const S s, const typename S::Vertex& in, typename S::Varyings& out,
             const FragCoord& frag, glm::vec4& color) {
        { s.vertex(in, out) } -> std::convertible_to<glm::vec4>;
        { s.fragment(out, frag, color) } -> std::convertible_to<bool>;
    };

// ---- what a shader may offer beyond vertex() and fragment()

// fragment_batch(varyings, z, front_facing, color): the same formulas on eight pixels at
// once, one simd::f8 per varying and per color channel; the back end then shades eight
// pixels of a row, or eight queued fragments (fragment_queue.h), at a time.
template <class S>
concept BatchShader = Shader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v,
                                           simd::f8 z, std::array<simd::f8, 4>& color) {
    s.fragment_batch(v, z, true, color);
};

// A shader may also offer fragment_pair(v0, v1, z0, z1, front_facing, color0, color1):
// fragment_batch for two groups at once, where doing both together is cheaper (a texture's
// lookups overlap, and share one level of detail where the two are a row of 2x2 quads' first
// row and the row below it). The back end then shades such rows, and the fragment queue's
// groups, two at a time.
template <class S>
concept PairShader = BatchShader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v,
                                                   simd::f8 z, std::array<simd::f8, 4>& color) {
    s.fragment_pair(v, v, z, z, true, color, color);
};

// And fragment_four(v, z, front_facing, color), v, z and color arrays of four: four groups,
// two neighbouring pairs as fragment_pair takes them (groups 0 and 1 the first pair's rows,
// 2 and 3 the next eight pixels' to the right) or any four, where four together are cheaper
// still.
template <class S>
concept FourShader = PairShader<S> && requires(const S s, const std::array<simd::f8, kVaryingCount<typename S::Varyings>> (&v)[4],
                                                       const simd::f8 (&z)[4], std::array<simd::f8, 4> (&color)[4]) {
    s.fragment_four(v, z, true, color);
};

// vertex_lanes(in, varyings, clip): vertex() for the eight vertices in[0..8) at once, a
// simd::f8 per varying and per clip coordinate, with the same arithmetic in the same order
// (the same bits). Vertex processing's AVX2 path then runs it in place of eight vertex()
// calls (vertex_processing.h).
template <class S>
concept LaneVertexShader = Shader<S> && requires(const S s, const typename S::Vertex* in,
                                                 std::array<simd::f8, kVaryingCount<typename S::Varyings>>& v, std::array<simd::f8, 4>& clip) {
    s.vertex_lanes(in, v, clip);
};

// A shader that never discards and has no side effects says so with
// `static constexpr bool kPure = true;`: its fragments' depth can be written before they
// are shaded, and they can be shaded in any order (fragment_queue.h,
// hidden_surface_removal.h).
template <class S>
concept PureShader = requires { requires S::kPure; };

}  // namespace softraster
