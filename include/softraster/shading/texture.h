// Textures and their sampling (spec "Textures"): 8-bit texels, (0, 0) at the bottom-left of
// the picture as displayed, texel centers at ((i + 0.5) / w, (j + 0.5) / h), nearest or
// bilinear (GL_LINEAR, no mipmaps) filtering, repeat or clamp-to-edge wrapping.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "softraster/image.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

enum class Filter { Nearest, Bilinear };
enum class Wrap { Repeat, Clamp };

class Texture {
public:
    explicit Texture(const Image& image);  // image row 0 is the top of the picture

    int width() const { return width_; }
    int height() const { return height_; }
    // Texel (i, j), j counted from the bottom row, as floats in [0, 1].
    glm::vec4 texel(int i, int j) const {
        const Rgba8 t = texels_[size_t(j) * size_t(width_) + size_t(i)];
        return glm::vec4(t.r, t.g, t.b, t.a) * (1.0f / 255.0f);
    }

    template <Filter F, Wrap W>
    glm::vec4 sample(glm::vec2 uv) const;
    // The same with filter and wrap chosen at run time.
    glm::vec4 sample(glm::vec2 uv, Filter f, Wrap w) const {
        if (f == Filter::Nearest) return w == Wrap::Repeat ? sample<Filter::Nearest, Wrap::Repeat>(uv) : sample<Filter::Nearest, Wrap::Clamp>(uv);
        return w == Wrap::Repeat ? sample<Filter::Bilinear, Wrap::Repeat>(uv) : sample<Filter::Bilinear, Wrap::Clamp>(uv);
    }
    // Eight lookups at once (u[l], v[l]) -> (r, g, b, a)[l], each as sample() computes it.
    // Out of line: the eight-pixel shaders call it from every tile loop they are inlined
    // into, and one compiled copy (a call per eight texels) keeps the build small.
    void sample8(const simd::f8& u, const simd::f8& v, Filter f, Wrap w, std::array<simd::f8, 4>& rgba) const;

private:
    int width_, height_;
    std::vector<Rgba8> texels_;  // bottom row first
};

namespace detail {
// Texel index i along an axis of n texels. Repeat wraps (GL_REPEAT); clamp stays on the
// edge texels (GL_CLAMP_TO_EDGE). Callers pass i in [-1, n] (coordinates are reduced
// first), so repeat needs no division.
template <Wrap W>
inline int wrap_texel(int i, int n) {
    if constexpr (W == Wrap::Repeat) {
        return i < 0 ? i + n : (i >= n ? i - n : i);
    } else {
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
    }
}
// floor(t) as an int, for any float: NaN and huge values are pinned to a safe range first
// (a float -> int conversion out of range is undefined behaviour).
inline int floor_to_int(float t) {
    if (!(t > -1.0e8f)) return -100000000;
    if (t > 1.0e8f) return 100000000;
    const int i = int(t);
    return float(i) > t ? i - 1 : i;
}
// Coordinate in [0, n) (repeat) or a bounded range (clamp) before scaling, so that texel
// arithmetic stays exact and in int range for any uv.
template <Wrap W>
inline float reduce(float u) {
    if constexpr (W == Wrap::Repeat) {
        if (!(u >= -1.0e6f && u <= 1.0e6f)) return 0.0f;
        return u - float(floor_to_int(u));
    } else {
        return u != u ? 0.0f : (u < -1.0f ? -1.0f : (u > 2.0f ? 2.0f : u));
    }
}
}  // namespace detail

template <Filter F, Wrap W>
glm::vec4 Texture::sample(glm::vec2 uv) const {
    const float u = detail::reduce<W>(uv.x) * float(width_);
    const float v = detail::reduce<W>(uv.y) * float(height_);
    if constexpr (F == Filter::Nearest) {
        return texel(detail::wrap_texel<W>(detail::floor_to_int(u), width_),
                     detail::wrap_texel<W>(detail::floor_to_int(v), height_));
    } else {
        // Blend the four nearest texel centers: texel i's center is at i + 0.5.
        const float x = u - 0.5f, y = v - 0.5f;
        const int i0 = detail::floor_to_int(x), j0 = detail::floor_to_int(y);
        const float fx = x - float(i0), fy = y - float(j0);
        const int ia = detail::wrap_texel<W>(i0, width_), ib = detail::wrap_texel<W>(i0 + 1, width_);
        const int ja = detail::wrap_texel<W>(j0, height_), jb = detail::wrap_texel<W>(j0 + 1, height_);
        const glm::vec4 bottom = texel(ia, ja) * (1.0f - fx) + texel(ib, ja) * fx;
        const glm::vec4 top = texel(ia, jb) * (1.0f - fx) + texel(ib, jb) * fx;
        return bottom * (1.0f - fy) + top * fy;
    }
}

}  // namespace softraster
