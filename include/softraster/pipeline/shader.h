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
#include <concepts>
#include <cstring>
#include <type_traits>

#include <glm/vec4.hpp>

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

template <class S>
concept Shader = VaryingStruct<typename S::Varyings> &&
    requires(const S s, const typename S::Vertex& in, typename S::Varyings& out,
             const FragCoord& frag, glm::vec4& color) {
        { s.vertex(in, out) } -> std::convertible_to<glm::vec4>;
        { s.fragment(out, frag, color) } -> std::convertible_to<bool>;
    };

}  // namespace softraster
