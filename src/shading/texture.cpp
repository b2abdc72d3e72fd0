#include "softraster/shading/texture.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace softraster {

namespace {

// Level k + 1 from level k as glGenerateMipmap's blit makes it: each texel the bilinear
// lookup (clamped to the edge) at its center mapped into level k. With even sizes that is
// exactly the average of the 2x2 texels under it; rounded to the nearest 8-bit value. An
// sRGB texture's r, g, b are decoded, filtered in linear light and encoded again.
std::vector<Rgba8> downsample(const std::vector<Rgba8>& src, int sw, int sh, int dw, int dh, bool srgb) {
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
            auto mix = [&](float pa, float pb, float pc, float pd) {
                const float bottom = pa * (1.0f - fx) + pb * fx, top = pc * (1.0f - fx) + pd * fx;
                return bottom * (1.0f - fy) + top * fy;
            };
            auto color = [&](uint8_t pa, uint8_t pb, uint8_t pc, uint8_t pd) {
                if (srgb) return srgb::encode(mix(srgb::decode(pa), srgb::decode(pb), srgb::decode(pc), srgb::decode(pd)));
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

}  // namespace

Texture::Texture(const Image& image, ColorSpace color) : srgb_(color == ColorSpace::Srgb) {
    if (image.width < 1 || image.height < 1) throw std::invalid_argument("texture image is empty");
    // The chain row by row first (downsample reads it so), then into tiles.
    std::vector<std::vector<Rgba8>> rows;
    std::vector<Rgba8> base(size_t(image.width) * size_t(image.height));
    for (int j = 0; j < image.height; ++j)  // flip: texel row 0 is the bottom of the picture
        for (int i = 0; i < image.width; ++i) base[size_t(j) * size_t(image.width) + size_t(i)] = image.at(i, image.height - 1 - j);
    rows.push_back(std::move(base));
    int offset = 0;
    for (int w = image.width, h = image.height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
        if (!levels_.empty()) rows.push_back(downsample(rows.back(), levels_.back().width, levels_.back().height, w, h, srgb_));
        const int tiles_x = (w + 3) / 4, tiles_y = (h + 3) / 4;
        levels_.push_back(Level{w, h, tiles_x, offset});
        offset += tiles_x * tiles_y * 16;
        if (w == 1 && h == 1) break;
    }
    for (size_t k = 0; k < 16; ++k) {
        const Level& l = levels_[std::min(k, levels_.size() - 1)];
        tables_.width[k] = l.width, tables_.height[k] = l.height, tables_.tiles_x[k] = l.tiles_x, tables_.offset[k] = l.offset;
    }
    storage_.assign(size_t(offset) + 15, 0u);
    aligned_ = (64 - reinterpret_cast<uintptr_t>(storage_.data()) % 64) % 64 / sizeof(uint32_t);
    uint32_t* out = storage_.data() + aligned_;
    for (size_t k = 0; k < levels_.size(); ++k) {
        const Level& l = levels_[k];
        for (int j = 0; j < l.height; ++j)
            for (int i = 0; i < l.width; ++i) {
                const Rgba8 t = rows[k][size_t(j) * size_t(l.width) + size_t(i)];
                out[texel_index(l, i, j)] = uint32_t(t.r) | uint32_t(t.g) << 8 | uint32_t(t.b) << 16 | uint32_t(t.a) << 24;
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
    auto at = [&](int level, glm::vec2 p) {
        return s.min == Filter::Nearest ? sample_level<Filter::Nearest>(level, p, s) : sample_level<Filter::Bilinear>(level, p, s);
    };
    auto lookup = [&](glm::vec2 p) {
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

// ---- eight lookups at once
//
// The arithmetic of select_lod and sample_level, lane by lane the same operations in the
// same order (so the bits agree with sample()), but on eight lanes: each lane may read
// another level (the level of detail is per 2x2 quad), so a level's size and offset are
// per lane too, and the four texels of each bilinear footprint are gathered.
namespace {

using simd::f8;
using simd::i8;

// detail::floor_to_int on eight lanes.
inline i8 floor_to_int8(f8 t) {
    const i8 i = simd::to_int(simd::select((t > -1.0e8f) & (t <= 1.0e8f), t, simd::splat(0.0f)));
    const i8 floored = simd::select(simd::to_float(i) > t, i - 1, i);
    return simd::select(t > 1.0e8f, simd::splat_i(100000000), simd::select(t > -1.0e8f, floored, simd::splat_i(-100000000)));
}

// detail::reduce on eight lanes (the wrap mode is the same for all).
inline f8 reduce8(f8 u, Wrap w) {
    if (w == Wrap::Repeat || w == Wrap::Mirror) {
        const bool mirror = w == Wrap::Mirror;
        const f8 r = u - (mirror ? 2.0f : 1.0f) * simd::to_float(floor_to_int8(u * (mirror ? 0.5f : 1.0f)));
        return simd::select((u >= -1.0e6f) & (u <= 1.0e6f), r, simd::splat(0.0f));
    }
    const f8 c = simd::select(u < -1.0f, simd::splat(-1.0f), simd::select(u > 2.0f, simd::splat(2.0f), u));
    return simd::select(u == u, c, simd::splat(0.0f));
}

// detail::wrap_texel on eight lanes, n texels per lane.
inline i8 wrap_texel8(i8 i, i8 n, Wrap w) {
    switch (w) {
        case Wrap::Repeat: return simd::select(i < 0, i + n, simd::select(i >= n, i - n, i));
        case Wrap::Clamp: return simd::select(i < 0, simd::splat_i(0), simd::select(i >= n, n - 1, i));
        case Wrap::Mirror: {
            const i8 n2 = n + n;
            const i8 m = simd::select(i < 0, i + n2, simd::select(i >= n2, i - n2, i));
            return simd::select(m < n, m, n2 - 1 - m);
        }
        case Wrap::Border: return simd::select((i < 0) | (i >= n), simd::splat_i(-1), i);
    }
    return i;
}

// out[k] = p[index[k]] for each lane: AVX2's gather on that path, a loop on the other. The
// vectors go by reference: where the AVX2 copy is not flattened into one function
// (sanitizer builds) this is a call from code compiled without AVX, which passes a 32-byte
// vector by value differently.
template <bool Wide>
inline void gather(const uint32_t* p, const i8& index, i8& out) {
    for (int k = 0; k < simd::kLanes; ++k) out[k] = int32_t(p[index[k]]);
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void gather<true>(const uint32_t* p, const i8& index, i8& out) {
    out = i8(_mm256_i32gather_epi32(reinterpret_cast<const int*>(p), __m256i(index), 4));
}
#endif

// A level's numbers, per lane.
struct LaneLevels {
    i8 width, height, tiles_x, offset;
};

}  // namespace

template <bool Wide, bool Srgb>
void Texture::sample_lanes(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    // Anisotropic filtering compiles to a copy of its own (Aniso), so that it costs the
    // other lookups nothing.
    auto body = [&]<bool Aniso>() {
        using simd::select, simd::splat, simd::splat_i, simd::to_float;
        // Which level(s) and filter each lane takes (select_lod).
        i8 level0 = splat_i(0), level1 = splat_i(0), nearest = splat_i(s.mag == Filter::Nearest ? -1 : 0), probes = splat_i(1);
        f8 weight = splat(0.0f), axis_u = splat(0.0f), axis_v = splat(0.0f);
        if (s.uses_lod()) {
            const f8 ax = d[0] * float(width()), bx = d[1] * float(height()), ay = d[2] * float(width()), by = d[3] * float(height());
            const f8 rx = ax * ax + bx * bx, ry = ay * ay + by * by;
            f8 rho2 = select(rx > ry, rx, ry);
            const i8 minified = rho2 > 1.0f;
            nearest = select(minified, splat_i(s.min == Filter::Nearest ? -1 : 0), nearest);
            if constexpr (Aniso) {  // probe_count and the long axis, lane by lane
                const f8 rmin = select(rx > ry, ry, rx);
                probes = splat_i(1);
                for (int k = 1; k < s.max_anisotropy; ++k) probes = select(to_float(splat_i(k * k)) * rmin < rho2, probes + 1, probes);
                probes = select(minified, probes, splat_i(1));
                axis_u = select(rx > ry, d[0], d[2]), axis_v = select(rx > ry, d[1], d[3]);
                rho2 = rho2 / to_float(probes * probes);
            }
            const i8 bits = std::bit_cast<i8>(rho2);
            const i8 exponent = ((bits >> 23) & 255) - 127;
            const int last = levels() - 1;
            if (s.mip == MipFilter::Nearest) {
                const i8 l = (exponent + 1) >> 1;
                level0 = level1 = select(minified, select(l < 0, splat_i(0), select(l > last, splat_i(last), l)), splat_i(0));
            } else if (s.mip == MipFilter::Linear) {
                const i8 mbits = (bits & 0x007fffff) | 0x3f800000;
                const f8 lod = 0.5f * (to_float(exponent) + (std::bit_cast<f8>(mbits) - 1.0f));
                const i8 i = floor_to_int8(lod);
                const i8 inside = minified & (i >= 0) & (i < last);
                level0 = select(minified & (i >= last), splat_i(last), select(inside, i, splat_i(0)));
                level1 = select(inside, i + 1, level0);
                weight = select(inside, lod - to_float(i), splat(0.0f));
            }
        }
        const bool two_levels = s.mip == MipFilter::Linear && simd::any(weight != 0.0f);
        auto lane_levels = [&](i8 level) {
            LaneLevels r{};
            if (!simd::any(level != 0)) {
                const Level& l = levels_[0];
                return LaneLevels{splat_i(l.width), splat_i(l.height), splat_i(l.tiles_x), splat_i(l.offset)};
            }
            if (levels() <= 16) {  // a texture under 65536 texels a side: two table lookups per number
                const i8 high = level >= 8, index = level & 7;
                auto pick = [&](const std::array<int32_t, 16>& table) {
                    i8 low_half, high_half;
                    std::memcpy(&low_half, table.data(), sizeof(i8));
                    std::memcpy(&high_half, table.data() + 8, sizeof(i8));
                    return select(high, simd::permute(high_half, index), simd::permute(low_half, index));
                };
                return LaneLevels{pick(tables_.width), pick(tables_.height), pick(tables_.tiles_x), pick(tables_.offset)};
            }
            for (int k = 0; k < simd::kLanes; ++k) {
                const Level& l = levels_[size_t(level[k])];
                r.width[k] = l.width, r.height[k] = l.height, r.tiles_x[k] = l.tiles_x, r.offset[k] = l.offset;
            }
            return r;
        };
        // sample_level: nearest lanes take the bilinear formula at x = u with weights 0, which
        // gives exactly the one texel (t * 1 + t' * 0 = t).
        const f8 half = select(nearest, splat(0.0f), splat(0.5f));
        const uint32_t* texels = this->texels();
        const std::array<float, 256>& decode = srgb::tables().decode;
        const bool has_border = s.wrap_s == Wrap::Border || s.wrap_t == Wrap::Border;
        auto at_level = [&](const LaneLevels& l, const f8& ur, const f8& vr, std::array<f8, 4>& out) {
            const f8 x = ur * to_float(l.width) - half, y = vr * to_float(l.height) - half;
            const i8 i0 = floor_to_int8(x), j0 = floor_to_int8(y);
            const f8 fx = select(nearest, splat(0.0f), x - to_float(i0)), fy = select(nearest, splat(0.0f), y - to_float(j0));
            const i8 ia = wrap_texel8(i0, l.width, s.wrap_s), ib = wrap_texel8(i0 + 1, l.width, s.wrap_s);
            const i8 ja = wrap_texel8(j0, l.height, s.wrap_t), jb = wrap_texel8(j0 + 1, l.height, s.wrap_t);
            std::array<f8, 4> c[4];  // the footprint's texels: (ia, ja), (ib, ja), (ia, jb), (ib, jb)
            const i8 is[4] = {ia, ib, ia, ib}, js[4] = {ja, ja, jb, jb};
            for (int t = 0; t < 4; ++t) {
                const i8 border = (is[t] < 0) | (js[t] < 0);  // (never without a border wrap mode)
                const i8 index = l.offset + ((js[t] >> 2) * l.tiles_x + (is[t] >> 2)) * 16 + (js[t] & 3) * 4 + (is[t] & 3);
                i8 texel;
                gather<Wide>(texels, has_border ? select(border, splat_i(0), index) : index, texel);
                for (int k = 0; k < 4; ++k) {
                    f8 value;
                    if (Srgb && k < 3) {  // decoded texel by texel, before the filter
                        const i8 byte = (texel >> (8 * k)) & 255;
                        for (int lane = 0; lane < simd::kLanes; ++lane) value[lane] = decode[size_t(byte[lane])];
                    } else {
                        value = to_float((texel >> (8 * k)) & 255) * (1.0f / 255.0f);
                    }
                    c[t][size_t(k)] = has_border ? select(border, splat(s.border[k]), value) : value;
                }
            }
            for (size_t k = 0; k < 4; ++k) {
                const f8 bottom = c[0][k] * (1.0f - fx) + c[1][k] * fx, top = c[2][k] * (1.0f - fx) + c[3][k] * fx;
                out[k] = bottom * (1.0f - fy) + top * fy;
            }
        };
        if constexpr (!Aniso) {
            const f8 ur = reduce8(u, s.wrap_s), vr = reduce8(v, s.wrap_t);
            at_level(lane_levels(level0), ur, vr, rgba);
            if (two_levels) {
                std::array<f8, 4> c1;
                at_level(lane_levels(level1), ur, vr, c1);
                for (size_t k = 0; k < 4; ++k) rgba[k] = rgba[k] + (c1[k] - rgba[k]) * weight;
            }
            return;
        }
        // Anisotropic: the same lookup at each probe (sample()'s loop); a lane adds its k-th
        // only while k < its N.
        const LaneLevels levels0 = lane_levels(level0), levels1 = two_levels ? lane_levels(level1) : levels0;
        auto lookup = [&](const f8& pu, const f8& pv, std::array<f8, 4>& out) {
            const f8 ur = reduce8(pu, s.wrap_s), vr = reduce8(pv, s.wrap_t);
            at_level(levels0, ur, vr, out);
            if (two_levels) {
                std::array<f8, 4> c1;
                at_level(levels1, ur, vr, c1);
                for (size_t k = 0; k < 4; ++k) out[k] = out[k] + (c1[k] - out[k]) * weight;
            }
        };
        int most_probes = 1;
        for (int lane = 0; lane < simd::kLanes; ++lane) most_probes = std::max(most_probes, int(probes[lane]));
        if (most_probes == 1) return lookup(u, v, rgba);
        rgba = {splat(0.0f), splat(0.0f), splat(0.0f), splat(0.0f)};
        for (int k = 0; k < most_probes; ++k) {
            const f8 t = to_float(splat_i(2 * k + 1)) / to_float(probes + probes) - 0.5f;
            const i8 used = splat_i(k) < probes, moved = probes > 1;  // (one probe: uv itself, as sample() reads it)
            std::array<f8, 4> probe;
            lookup(select(moved, u + t * axis_u, u), select(moved, v + t * axis_v, v), probe);
            for (size_t c = 0; c < 4; ++c) rgba[c] = rgba[c] + select(used, probe[c], splat(0.0f));
        }
        for (size_t c = 0; c < 4; ++c) rgba[c] = rgba[c] / to_float(probes);
    };
    if (s.max_anisotropy > 1) body.template operator()<true>();
    else body.template operator()<false>();
}

// In the CPU's best copy (simd.h).
void Texture::sample8(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    simd::on_best_path([&]<bool Wide>() {
        if (srgb_) sample_lanes<Wide, true>(u, v, d, s, rgba);
        else sample_lanes<Wide, false>(u, v, d, s, rgba);
    });
}

}  // namespace softraster
