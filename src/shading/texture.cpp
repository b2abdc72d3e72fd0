#include "softraster/shading/texture.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace softraster {

namespace {

// Level k + 1 from level k as glGenerateMipmap's blit makes it: each texel the bilinear
// lookup (clamped to the edge) at its center mapped into level k. With even sizes that is
// exactly the average of the 2x2 texels under it; rounded to the nearest 8-bit value.
std::vector<Rgba8> downsample(const std::vector<Rgba8>& src, int sw, int sh, int dw, int dh) {
    std::vector<Rgba8> dst(size_t(dw) * size_t(dh));
    const float sx = float(sw) / float(dw), sy = float(sh) / float(dh);
    auto at = [&](int i, int j) {
        i = std::clamp(i, 0, sw - 1), j = std::clamp(j, 0, sh - 1);
        return src[size_t(j) * size_t(sw) + size_t(i)];
    };
    for (int j = 0; j < dh; ++j)
        for (int i = 0; i < dw; ++i) {
            const float x = (float(i) + 0.5f) * sx - 0.5f, y = (float(j) + 0.5f) * sy - 0.5f;
            const int i0 = detail::floor_to_int(x), j0 = detail::floor_to_int(y);
            const float fx = x - float(i0), fy = y - float(j0);
            const Rgba8 a = at(i0, j0), b = at(i0 + 1, j0), c = at(i0, j0 + 1), d = at(i0 + 1, j0 + 1);
            auto mix = [&](uint8_t pa, uint8_t pb, uint8_t pc, uint8_t pd) {
                const float bottom = float(pa) * (1.0f - fx) + float(pb) * fx, top = float(pc) * (1.0f - fx) + float(pd) * fx;
                return uint8_t(std::min(255.0f, std::floor(bottom * (1.0f - fy) + top * fy + 0.5f)));
            };
            dst[size_t(j) * size_t(dw) + size_t(i)] = {mix(a.r, b.r, c.r, d.r), mix(a.g, b.g, c.g, d.g), mix(a.b, b.b, c.b, d.b),
                                                       mix(a.a, b.a, c.a, d.a)};
        }
    return dst;
}

// floor(log2(x)) from the float's exponent field, and the fraction x / 2^floor(log2(x)) in
// [1, 2): exact for normal numbers; 0 and denormals give -127, infinity and NaN 128.
inline int exponent_of(float x) { return int((std::bit_cast<uint32_t>(x) >> 23) & 255u) - 127; }
inline float mantissa_of(float x) { return std::bit_cast<float>((std::bit_cast<uint32_t>(x) & 0x007fffffu) | 0x3f800000u); }

}  // namespace

Texture::Texture(const Image& image) {
    if (image.width < 1 || image.height < 1) throw std::invalid_argument("texture image is empty");
    Level base{image.width, image.height, std::vector<Rgba8>(size_t(image.width) * size_t(image.height))};
    for (int j = 0; j < base.height; ++j)  // flip: texel row 0 is the bottom of the picture
        for (int i = 0; i < base.width; ++i) base.texels[size_t(j) * size_t(base.width) + size_t(i)] = image.at(i, base.height - 1 - j);
    levels_.push_back(std::move(base));
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& l = levels_.back();
        const int w = std::max(1, l.width / 2), h = std::max(1, l.height / 2);
        levels_.push_back(Level{w, h, downsample(l.texels, l.width, l.height, w, h)});
    }
}

// The level of detail as llvmpipe computes it (Mesa's lp_bld_sample.c with its default
// settings: exact rho, no "brilinear"), one value per 2x2 quad:
//   rho^2 = max((du/dx W)^2 + (dv/dx H)^2, (du/dy W)^2 + (dv/dy H)^2)   (W x H: level 0)
//   minified when rho^2 > 1;
//   nearest mip level: round(log2(rho)), as floor((floor(log2(rho^2)) + 1) / 2);
//   linear between levels: lod = log2(rho^2) / 2 with log2(x) approximated piecewise linearly
//   between powers of two (log2(m 2^e) ~ e + m - 1, exact at powers of two); levels floor(lod)
//   and the next, weighted by lod - floor(lod), both clamped to the chain (weight 0 there).
LevelChoice Texture::select_lod(const UvDerivatives& d, const Sampler& s) const {
    const float w = float(width()), h = float(height());
    const float ax = d.dudx * w, bx = d.dvdx * h, ay = d.dudy * w, by = d.dvdy * h;
    const float rx = ax * ax + bx * bx, ry = ay * ay + by * by;
    const float rho2 = rx > ry ? rx : ry;
    const int last = levels() - 1;
    LevelChoice c;
    c.minified = rho2 > 1.0f;
    if (!c.minified || s.mip == MipFilter::None) return c;
    if (s.mip == MipFilter::Nearest) {
        c.level0 = c.level1 = std::clamp((exponent_of(rho2) + 1) >> 1, 0, last);
        return c;
    }
    const float lod = 0.5f * (float(exponent_of(rho2)) + (mantissa_of(rho2) - 1.0f));
    const int i = detail::floor_to_int(lod);
    if (i >= last) {
        c.level0 = c.level1 = last;
    } else if (i >= 0) {
        c.level0 = i, c.level1 = i + 1;
        c.weight = lod - float(i);
    }
    return c;
}

template <Filter F>
glm::vec4 Texture::sample_level(int level, glm::vec2 uv, const Sampler& s) const {
    const Level& l = levels_[size_t(level)];
    const float u = detail::reduce(uv.x, s.wrap_s) * float(l.width);
    const float v = detail::reduce(uv.y, s.wrap_t) * float(l.height);
    auto fetch = [&](int i, int j) { return i < 0 || j < 0 ? s.border : texel(level, i, j); };  // (-1: the border)
    if constexpr (F == Filter::Nearest) {
        return fetch(detail::wrap_texel(detail::floor_to_int(u), l.width, s.wrap_s),
                     detail::wrap_texel(detail::floor_to_int(v), l.height, s.wrap_t));
    } else {
        // Blend the four nearest texel centers: texel i's center is at i + 0.5.
        const float x = u - 0.5f, y = v - 0.5f;
        const int i0 = detail::floor_to_int(x), j0 = detail::floor_to_int(y);
        const float fx = x - float(i0), fy = y - float(j0);
        const int ia = detail::wrap_texel(i0, l.width, s.wrap_s), ib = detail::wrap_texel(i0 + 1, l.width, s.wrap_s);
        const int ja = detail::wrap_texel(j0, l.height, s.wrap_t), jb = detail::wrap_texel(j0 + 1, l.height, s.wrap_t);
        const glm::vec4 bottom = fetch(ia, ja) * (1.0f - fx) + fetch(ib, ja) * fx;
        const glm::vec4 top = fetch(ia, jb) * (1.0f - fx) + fetch(ib, jb) * fx;
        return bottom * (1.0f - fy) + top * fy;
    }
}

glm::vec4 Texture::sample(glm::vec2 uv, const Sampler& s) const {
    return s.mag == Filter::Nearest ? sample_level<Filter::Nearest>(0, uv, s) : sample_level<Filter::Bilinear>(0, uv, s);
}

glm::vec4 Texture::sample(glm::vec2 uv, const UvDerivatives& d, const Sampler& s) const {
    if (!s.uses_lod()) return sample(uv, s);
    const LevelChoice c = select_lod(d, s);
    if (!c.minified) return sample(uv, s);
    auto at = [&](int level) {
        return s.min == Filter::Nearest ? sample_level<Filter::Nearest>(level, uv, s) : sample_level<Filter::Bilinear>(level, uv, s);
    };
    const glm::vec4 c0 = at(c.level0);
    if (c.weight == 0.0f) return c0;
    return c0 + (at(c.level1) - c0) * c.weight;
}

namespace {
// flatten: the lookup inlined into the lane loop (left to itself GCC calls it per lane).
[[gnu::flatten]] void sample_lanes(const Texture& t, const simd::f8& u, const simd::f8& v, const std::array<simd::f8, 4>& d,
                                   const Sampler& s, std::array<simd::f8, 4>& rgba) {
    for (int l = 0; l < simd::kLanes; ++l) {
        const glm::vec4 c = t.sample(glm::vec2(u[l], v[l]), UvDerivatives{d[0][l], d[1][l], d[2][l], d[3][l]}, s);
        for (int k = 0; k < 4; ++k) rgba[size_t(k)][l] = c[k];
    }
}
}  // namespace

// In the CPU's best copy (simd.h), lane by lane with sample()'s arithmetic.
void Texture::sample8(const simd::f8& u, const simd::f8& v, const std::array<simd::f8, 4>& d, const Sampler& s,
                      std::array<simd::f8, 4>& rgba) const {
    simd::on_best_path([&]<bool>() { sample_lanes(*this, u, v, d, s, rgba); });
}

}  // namespace softraster
