// The texture at load (its mipmap chain, in apron tiles) and the one-point lookups that
// define every result; the eight-lane copy of them is texture_lanes.cpp.
#include "softraster/shading/texture.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace softraster {

namespace {

// Level k + 1 from level k as glGenerateMipmap's blit makes it: each texel the bilinear
// lookup (clamped to the edge) at its center mapped into level k. With even sizes that is
// exactly the average of the 2x2 texels under it; rounded to the nearest 8-bit value. An
// sRGB texture's r, g, b are decoded, filtered in linear light and encoded again.
std::vector<Rgba8> downsample(const std::vector<Rgba8>& src, int sw, int sh, int dw, int dh, bool srgb) {
    std::vector<Rgba8> dst(size_t(dw) * size_t(dh));
    const float sx = float(sw) / float(dw), sy = float(sh) / float(dh);
    const srgb::Tables& tables = srgb::tables();
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
            auto mix = [&](float pa, float pb, float pc, float pd) {
                const float bottom = pa * (1.0f - fx) + pb * fx, top = pc * (1.0f - fx) + pd * fx;
                return bottom * (1.0f - fy) + top * fy;
            };
            auto color = [&](uint8_t pa, uint8_t pb, uint8_t pc, uint8_t pd) {
                if (srgb) return srgb::encode(tables, mix(tables.decode[pa], tables.decode[pb], tables.decode[pc], tables.decode[pd]));
                return uint8_t(std::min(255.0f, std::floor(mix(float(pa), float(pb), float(pc), float(pd)) + 0.5f)));
            };
            const float alpha = mix(float(a.a), float(b.a), float(c.a), float(d.a));
            dst[size_t(j) * size_t(dw) + size_t(i)] = {color(a.r, b.r, c.r, d.r), color(a.g, b.g, c.g, d.g), color(a.b, b.b, c.b, d.b),
                                                       uint8_t(std::min(255.0f, std::floor(alpha + 0.5f)))};
        }
    return dst;
}

// floor(log2(x)) from the float's exponent field, and the fraction x / 2^floor(log2(x)) in
// [1, 2): exact for normal numbers; 0 and denormals give -127, infinity and NaN 128.
inline int exponent_of(float x) { return int((std::bit_cast<uint32_t>(x) >> 23) & 255u) - 127; }
inline float mantissa_of(float x) { return std::bit_cast<float>((std::bit_cast<uint32_t>(x) & 0x007fffffu) | 0x3f800000u); }

// Anisotropic filtering as EXT_texture_filter_anisotropic describes it: with P_max and P_min
// the lengths of the footprint's longer and shorter axes (in texels of level 0), N =
// min(ceil(P_max / P_min), max) lookups along the longer axis, each at the level of detail
// of P_max / N. N is the smallest n with n^2 P_min^2 >= P_max^2, found by comparisons (exact,
// the same on every path, no square root); a footprint of zero width takes the maximum.
inline int probe_count(float rmax, float rmin, int max_anisotropy) {
    int n = 1;
    for (int k = 1; k < max_anisotropy; ++k) n += float(k * k) * rmin < rmax ? 1 : 0;
    return n;
}

// The texel indices of a bilinear footprint whose lower-left texel is (i0, j0), each wrapped
// (-1: the border color).
struct Footprint {
    int ia, ib, ja, jb;
};
// p + (q - p) w / 2^bits (w < 2^bits) as sixteen-bit lanes compute it with two high-half
// products (sample_lanes): p - (p w >> bits) + (q w >> bits), within p..q.
inline int blend_fixed(int p, int q, int w, int bits) { return p - ((p * w) >> bits) + ((q * w) >> bits); }

inline Footprint footprint(int i0, int j0, int width, int height, const Sampler& s) {
    return {detail::wrap_texel(i0, width, s.wrap_s), detail::wrap_texel(i0 + 1, width, s.wrap_s), detail::wrap_texel(j0, height, s.wrap_t),
            detail::wrap_texel(j0 + 1, height, s.wrap_t)};
}

}  // namespace

Texture::Texture(const Image& image, ColorSpace color) : srgb_(color == ColorSpace::Srgb) {
    if (image.width < 1 || image.height < 1) throw std::invalid_argument("texture image is empty");
    if (image.width > kMaxSide || image.height > kMaxSide) throw std::invalid_argument("texture image is wider or taller than 65536 texels");
    // The chain row by row first (downsample reads it so), then into tiles.
    std::vector<std::vector<Rgba8>> rows;
    std::vector<Rgba8> base(size_t(image.width) * size_t(image.height));
    for (int j = 0; j < image.height; ++j)  // flip: texel row 0 is the bottom of the picture
        for (int i = 0; i < image.width; ++i) base[size_t(j) * size_t(image.width) + size_t(i)] = image.at(i, image.height - 1 - j);
    rows.push_back(std::move(base));
    // (The lanes index texels with 32-bit integers: the whole chain must stay below 2^31,
    // checked before any level is averaged.)
    int64_t offset = 0;
    for (int w = image.width, h = image.height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
        const int tiles_x = (w + 3) / 4, tiles_y = (h + 3) / 4;
        levels_.push_back(Level{w, h, tiles_x, int(offset)});
        offset += int64_t(tiles_x) * int64_t(tiles_y) * kTileTexels;
        if (offset > int64_t(INT32_MAX) - 64) throw std::invalid_argument("texture image has too many texels (its tiles and mipmaps need 2^31 or more)");
        if (w == 1 && h == 1) break;
    }
    for (size_t k = 1; k < levels_.size(); ++k)
        rows.push_back(downsample(rows.back(), levels_[k - 1].width, levels_[k - 1].height, levels_[k].width, levels_[k].height, srgb_));
    for (size_t k = 0; k < 16; ++k) {
        const Level& l = levels_[std::min(k, levels_.size() - 1)];
        tables_.width[k] = l.width, tables_.height[k] = l.height, tables_.tiles_x[k] = l.tiles_x, tables_.offset[k] = l.offset;
        const int level = int(std::min(k, levels_.size() - 1));
        tables_.shift_u[k] = std::min(level, int(std::bit_width(unsigned(image.width))) - 1);
        tables_.shift_v[k] = std::min(level, int(std::bit_width(unsigned(image.height))) - 1);
        tables_.mask_w[k] = l.width - 1, tables_.mask_h[k] = l.height - 1;
        tables_.log2_tiles_x[k] = int(std::bit_width(unsigned(l.tiles_x))) - 1;
    }
    pot_ = std::has_single_bit(unsigned(image.width)) && std::has_single_bit(unsigned(image.height));
    // One copy of the texels: a linear texture's bytes, or an sRGB texture's decoded onto the
    // fixed-point scale (fixed_texels). (The slack: the alignment below, and for a linear
    // texture 7 texels for the footprint loads' reach, texture_lanes.h.)
    uint32_t* out = nullptr;
    uint64_t* fixed = nullptr;
    if (srgb_) {
        fixed_storage_.assign(size_t(offset) + 7, 0u);
        fixed_aligned_ = (64 - reinterpret_cast<uintptr_t>(fixed_storage_.data()) % 64) % 64 / sizeof(uint64_t);
        fixed = fixed_storage_.data() + fixed_aligned_;
    } else {
        storage_.assign(size_t(offset) + 15 + 7, 0u);
        aligned_ = (64 - reinterpret_cast<uintptr_t>(storage_.data()) % 64) % 64 / sizeof(uint32_t);
        out = storage_.data() + aligned_;
    }
    const std::array<uint16_t, 256>& decode = srgb::tables().decode_fixed;
    // Tile by tile, apron and padding included: place (x, y) of tile (tx, ty) holds texel
    // (4 tx + x, 4 ty + y), wrapped as repeat wraps.
    for (size_t k = 0; k < levels_.size(); ++k) {
        const Level& l = levels_[k];
        const int tiles_y = (l.height + 3) / 4;
        size_t at = size_t(l.offset);
        for (int ty = 0; ty < tiles_y; ++ty)
            for (int tx = 0; tx < l.tiles_x; ++tx)
                for (int y = 0; y < kTileSide; ++y)
                    for (int x = 0; x < kTileSide; ++x, ++at) {
                        int i = 4 * tx + x, j = 4 * ty + y;  // (a division only past the edge)
                        if (i >= l.width) i %= l.width;
                        if (j >= l.height) j %= l.height;
                        const Rgba8 t = rows[k][size_t(j) * size_t(l.width) + size_t(i)];
                        if (fixed)
                            fixed[at] = uint64_t(decode[t.r]) | uint64_t(decode[t.g]) << 16 | uint64_t(decode[t.b]) << 32 |
                                        uint64_t(t.a) << 56;  // (alpha: 256 a)
                        else
                            out[at] = uint32_t(t.r) | uint32_t(t.g) << 8 | uint32_t(t.b) << 16 | uint32_t(t.a) << 24;
                    }
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
    float rho2 = rx > ry ? rx : ry;
    const int last = levels() - 1;
    LevelChoice c;
    c.minified = rho2 > 1.0f;
    if (!c.minified) return c;
    if (s.max_anisotropy > 1) {  // N lookups along the longer axis; its level from rho / N
        c.probes = probe_count(rho2, rx > ry ? ry : rx, s.max_anisotropy);
        c.axis_u = rx > ry ? d.dudx : d.dudy, c.axis_v = rx > ry ? d.dvdx : d.dvdy;
        rho2 = rho2 / float(c.probes * c.probes);  // (N = 1: the isotropic rho^2, bit for bit)
    }
    if (s.mip == MipFilter::None) return c;
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
        const Footprint f = footprint(i0, j0, l.width, l.height, s);
        const glm::vec4 bottom = fetch(f.ia, f.ja) * (1.0f - fx) + fetch(f.ib, f.ja) * fx;
        const glm::vec4 top = fetch(f.ia, f.jb) * (1.0f - fx) + fetch(f.ib, f.jb) * fx;
        return bottom * (1.0f - fy) + top * fy;
    }
}

// The fixed-point lookup (texture.h "Precision"): the sample point in 1/2^n texel steps
// (n = fraction_bits: 8, or 12 for sRGB),
//   x = floor(2^n (u w)) - 2^(n-1)   (bilinear: texel i's center is at i + 0.5; nearest: - 0)
// with u w rounded to a float once, so that on a power-of-two texture, where u w is exact,
// each level's x is level 0's shifted right (sample_lanes). Then per channel, with texels
// a, b below and c, d above (b, d to the right) on the scale 0..65280 (256 times an 8-bit
// value; an sRGB texel's r, g, b decoded, srgb::Tables::decode_fixed) and weights fx, fy in
// 0..2^n - 1:
//   bottom = a - (a fx >> n) + (b fx >> n),  top = c - (c fx >> n) + (d fx >> n)
//   value  = bottom - (bottom fy >> n) + (top fy >> n)          (0..65280)
// For a linear texture, a = 256 a8, the rows are exact: 256 a8 + (b8 - a8) fx. Each line is
// how sixteen-bit lanes compute p + (q - p) w / 2^n with two high-half products
// (sample_lanes); it stays within 0..65280.
template <Filter F>
glm::ivec4 Texture::sample_level_fixed(int level, glm::vec2 uv, const Sampler& s) const {
    const Level& l = levels_[size_t(level)];
    const int bits = fraction_bits(srgb_), one = 1 << bits, half = F == Filter::Nearest ? 0 : one / 2;
    const int x = detail::floor_bounded(detail::reduce(uv.x, s.wrap_s) * float(l.width) * float(one)) - half;
    const int y = detail::floor_bounded(detail::reduce(uv.y, s.wrap_t) * float(l.height) * float(one)) - half;
    const int fx = F == Filter::Nearest ? 0 : x & (one - 1), fy = F == Filter::Nearest ? 0 : y & (one - 1);
    const Footprint f = footprint(x >> bits, y >> bits, l.width, l.height, s);
    // Each texel's four channels on the fixed-point scale: an sRGB texture's as stored decoded
    // (fixed_texels, which the eight-lane filter reads too), a linear one's bytes times 256.
    auto texel_fixed = [&](int i, int j) {
        const size_t at = texel_index(l, i, j);
        if (srgb_) {
            const uint64_t t = fixed_texels()[at];
            return glm::ivec4(int(t & 0xffffu), int((t >> 16) & 0xffffu), int((t >> 32) & 0xffffu), int(t >> 48));
        }
        const uint32_t t = texels()[at];
        return glm::ivec4(int(t & 255u), int((t >> 8) & 255u), int((t >> 16) & 255u), int(t >> 24)) * 256;
    };
    const glm::ivec4 a = texel_fixed(f.ia, f.ja), b = texel_fixed(f.ib, f.ja), c = texel_fixed(f.ia, f.jb), d = texel_fixed(f.ib, f.jb);
    glm::ivec4 r;
    for (int k = 0; k < 4; ++k) r[k] = blend_fixed(blend_fixed(a[k], b[k], fx, bits), blend_fixed(c[k], d[k], fx, bits), fy, bits);
    return r;
}

namespace {
// Two fixed-point lookups blended by a weight of `bits` bits, as one level's rows are blended.
glm::ivec4 blend_fixed(const glm::ivec4& v0, const glm::ivec4& v1, float weight, int bits) {
    const int w = detail::floor_to_int(weight * float(1 << bits));  // (weight < 1: 0..2^bits - 1)
    glm::ivec4 r;
    for (int k = 0; k < 4; ++k) r[k] = blend_fixed(v0[k], v1[k], w, bits);
    return r;
}
glm::vec4 unit_of_fixed(const glm::ivec4& v) { return glm::vec4(v) * Texture::kFixedToUnit; }
}  // namespace

glm::vec4 Texture::sample(glm::vec2 uv, const Sampler& s) const {
    if (fixed_point(s))
        return unit_of_fixed(s.mag == Filter::Nearest ? sample_level_fixed<Filter::Nearest>(0, uv, s) : sample_level_fixed<Filter::Bilinear>(0, uv, s));
    return s.mag == Filter::Nearest ? sample_level<Filter::Nearest>(0, uv, s) : sample_level<Filter::Bilinear>(0, uv, s);
}

glm::vec4 Texture::sample(glm::vec2 uv, const UvDerivatives& d, const Sampler& s) const {
    if (!s.uses_lod()) return sample(uv, s);
    const LevelChoice c = select_lod(d, s);
    if (!c.minified) return sample(uv, s);
    auto at = [&](int level, glm::vec2 p) {
        return s.min == Filter::Nearest ? sample_level<Filter::Nearest>(level, p, s) : sample_level<Filter::Bilinear>(level, p, s);
    };
    auto lookup = [&](glm::vec2 p) {
        if (fixed_point(s)) {
            auto at_fixed = [&](int level) {
                return s.min == Filter::Nearest ? sample_level_fixed<Filter::Nearest>(level, p, s) : sample_level_fixed<Filter::Bilinear>(level, p, s);
            };
            const glm::ivec4 c0 = at_fixed(c.level0);
            return unit_of_fixed(c.weight == 0.0f ? c0 : blend_fixed(c0, at_fixed(c.level1), c.weight, fraction_bits(srgb_)));
        }
        const glm::vec4 c0 = at(c.level0, p);
        if (c.weight == 0.0f) return c0;
        return c0 + (at(c.level1, p) - c0) * c.weight;
    };
    if (c.probes == 1) return lookup(uv);
    glm::vec4 sum(0.0f);
    for (int k = 0; k < c.probes; ++k) {
        const float t = float(2 * k + 1) / float(2 * c.probes) - 0.5f;
        sum += lookup(glm::vec2(uv.x + t * c.axis_u, uv.y + t * c.axis_v));
    }
    const float n = float(c.probes);
    return {sum.x / n, sum.y / n, sum.z / n, sum.w / n};
}

}  // namespace softraster
