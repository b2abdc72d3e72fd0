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

// The texel indices of a bilinear footprint whose lower-left texel is (i0, j0), each wrapped
// (-1: the border color).
struct Footprint {
    int ia, ib, ja, jb;
};
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
    }
    pot_ = std::has_single_bit(unsigned(image.width)) && std::has_single_bit(unsigned(image.height));
    storage_.assign(size_t(offset) + 15, 0u);
    aligned_ = (64 - reinterpret_cast<uintptr_t>(storage_.data()) % 64) % 64 / sizeof(uint32_t);
    uint32_t* out = storage_.data() + aligned_;
    // Tile by tile, apron and padding included: place (x, y) of tile (tx, ty) holds texel
    // (4 tx + x, 4 ty + y), wrapped as repeat wraps.
    for (size_t k = 0; k < levels_.size(); ++k) {
        const Level& l = levels_[k];
        const int tiles_y = (l.height + 3) / 4;
        uint32_t* tile = out + l.offset;
        for (int ty = 0; ty < tiles_y; ++ty)
            for (int tx = 0; tx < l.tiles_x; ++tx, tile += kTileTexels)
                for (int y = 0; y < kTileSide; ++y)
                    for (int x = 0; x < kTileSide; ++x) {
                        const int i = (4 * tx + x) % l.width, j = (4 * ty + y) % l.height;
                        const Rgba8 t = rows[k][size_t(j) * size_t(l.width) + size_t(i)];
                        tile[y * kTileSide + x] = uint32_t(t.r) | uint32_t(t.g) << 8 | uint32_t(t.b) << 16 | uint32_t(t.a) << 24;
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

// The fixed-point lookup (texture.h "Precision"): the sample point in 1/256 texel steps, and
// per channel, with texels a, b below and c, d above (b, d to the right) and weights fx, fy
// in 0..255:
//   bottom = 256 a + (b - a) fx,  top = 256 c + (d - c) fx     (exact, 0..65280)
//   value  = bottom - (bottom fy >> 8) + (top fy >> 8)          (0..65280)
// The last line is how sixteen-bit lanes compute bottom + (top - bottom) fy / 256 with two
// high-half products (sample_lanes); it stays within 0..65280.
template <Filter F>
glm::ivec4 Texture::sample_level_fixed(int level, glm::vec2 uv, const Sampler& s) const {
    const Level& l = levels_[size_t(level)];
    const float half = F == Filter::Nearest ? 0.0f : 0.5f;  // (texel i's center is at i + 0.5)
    const int x = detail::floor_to_int((detail::reduce(uv.x, s.wrap_s) * float(l.width) - half) * 256.0f);
    const int y = detail::floor_to_int((detail::reduce(uv.y, s.wrap_t) * float(l.height) - half) * 256.0f);
    const int fx = F == Filter::Nearest ? 0 : x & 255, fy = F == Filter::Nearest ? 0 : y & 255;
    const Footprint f = footprint(x >> 8, y >> 8, l.width, l.height, s);
    const uint32_t a = texels()[texel_index(l, f.ia, f.ja)], b = texels()[texel_index(l, f.ib, f.ja)];
    const uint32_t c = texels()[texel_index(l, f.ia, f.jb)], d = texels()[texel_index(l, f.ib, f.jb)];
    glm::ivec4 r;
    for (int k = 0; k < 4; ++k) {
        auto channel = [k](uint32_t t) { return int((t >> (8 * k)) & 255u); };
        const int bottom = channel(a) * 256 + (channel(b) - channel(a)) * fx, top = channel(c) * 256 + (channel(d) - channel(c)) * fx;
        r[k] = bottom - ((bottom * fy) >> 8) + ((top * fy) >> 8);
    }
    return r;
}

namespace {
// Two fixed-point lookups blended by an 8-bit weight, as one level's rows are blended.
glm::ivec4 blend_fixed(const glm::ivec4& v0, const glm::ivec4& v1, float weight) {
    const int w = detail::floor_to_int(weight * 256.0f);  // (weight < 1: 0..255)
    glm::ivec4 r;
    for (int k = 0; k < 4; ++k) r[k] = v0[k] - ((v0[k] * w) >> 8) + ((v1[k] * w) >> 8);
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
            return unit_of_fixed(c.weight == 0.0f ? c0 : blend_fixed(c0, at_fixed(c.level1), c.weight));
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

// ---- eight lookups at once
//
// The arithmetic of select_lod and sample_level, lane by lane the same operations in the
// same order (so the bits agree with sample()), but on eight lanes: each lane may read
// another level (the level of detail is per 2x2 quad), so a level's size and offset are
// per lane too, and the four texels of each bilinear footprint are gathered.
namespace {

using simd::f8;
using simd::i8;

// detail::floor_to_int on eight lanes, for |t| < 2^31 (texel coordinates after reduce8,
// levels of detail): the same value without detail::floor_to_int's guards.
inline i8 floor_small8(const f8& t) {
    const i8 i = simd::to_int(t);
    return i + (simd::to_float(i) > t);  // (a true comparison is -1)
}

// detail::reduce on eight lanes (the wrap mode is the same for all).
inline f8 reduce8(f8 u, Wrap w) {
    if (w == Wrap::Repeat || w == Wrap::Mirror) {
        const bool mirror = w == Wrap::Mirror;
        const f8 in = simd::select((u >= -1.0e6f) & (u <= 1.0e6f), u, simd::splat(0.0f));  // (out of range: 0, as reduce)
        return in - (mirror ? 2.0f : 1.0f) * simd::to_float(floor_small8(in * (mirror ? 0.5f : 1.0f)));
    }
    const f8 c = simd::select(u < -1.0f, simd::splat(-1.0f), simd::select(u > 2.0f, simd::splat(2.0f), u));
    return simd::select(u == u, c, simd::splat(0.0f));
}

// detail::wrap_texel on eight lanes, n texels per lane. Pot: n is a power of two, and i is
// in [-1, 2n] (as wrap_texel asks): repeat is then i mod n, the low bits.
template <bool Pot>
inline i8 wrap_texel8(i8 i, i8 n, Wrap w) {
    if (Pot && w == Wrap::Repeat) return i & (n - 1);
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

// Texture::texel_index on eight lanes.
inline i8 tile_index8(const LaneLevels& l, const i8& i, const i8& j) {
    return l.offset + ((j >> 2) * l.tiles_x + (i >> 2)) * Texture::kTileTexels + (j & 3) * Texture::kTileSide + (i & 3);
}

// The four texels of each lane's bilinear footprint in the apron layout (texture.h): the
// texel at the index, its right neighbour, and the two above them, one tile row (5) on.
template <bool Wide>
inline void load_footprints(const uint32_t* p, const i8& index, i8 (&texel)[4]) {
    for (int k = 0; k < simd::kLanes; ++k) {
        const uint32_t* t = p + index[k];
        texel[0][k] = int32_t(t[0]), texel[1][k] = int32_t(t[1]);
        texel[2][k] = int32_t(t[Texture::kTileSide]), texel[3][k] = int32_t(t[Texture::kTileSide + 1]);
    }
}
#if SOFTRASTER_HAS_AVX2_PATH
// Two 8-byte loads per lane, (a, b) and (c, d), make its footprint in one 16-byte register;
// lanes k and k + 4 share a 32-byte one, and a 4x4 transpose in each half turns the four
// into the footprint's texels across the lanes: far cheaper here than four gathers.
template <>
[[gnu::target("avx2")]] inline void load_footprints<true>(const uint32_t* p, const i8& index, i8 (&texel)[4]) {
    alignas(32) int32_t at[simd::kLanes];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), __m256i(index));
    auto lane = [&](int k) {
        const uint32_t* t = p + at[k];
        const __m128 low = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(t)));
        return _mm_castps_si128(_mm_loadh_pi(low, reinterpret_cast<const __m64*>(t + Texture::kTileSide)));
    };
    __m256i y[4];
    for (int k = 0; k < 4; ++k) y[k] = _mm256_inserti128_si256(_mm256_castsi128_si256(lane(k)), lane(k + 4), 1);
    const __m256i ab01 = _mm256_unpacklo_epi32(y[0], y[1]), cd01 = _mm256_unpackhi_epi32(y[0], y[1]);
    const __m256i ab23 = _mm256_unpacklo_epi32(y[2], y[3]), cd23 = _mm256_unpackhi_epi32(y[2], y[3]);
    texel[0] = i8(_mm256_unpacklo_epi64(ab01, ab23)), texel[1] = i8(_mm256_unpackhi_epi64(ab01, ab23));
    texel[2] = i8(_mm256_unpacklo_epi64(cd01, cd23)), texel[3] = i8(_mm256_unpackhi_epi64(cd01, cd23));
}
#endif

// ---- the fixed-point filter on sixteen-bit lanes (sample_level_fixed)
//
// One gather's eight texels make two registers of sixteen 16-bit lanes: texels 0-3 in `lo`,
// 4-7 in `hi`, each texel's r, g, b, a in four lanes. A blend then works on two texels'
// channels at once, sixteen at a time, instead of eight float lanes per channel.
using u16x16 = uint16_t __attribute__((vector_size(32)));
struct Fixed8 {
    u16x16 lo, hi;
};

// The texels' bytes, widened to 16 bits. (The vector code is the specification; the AVX2
// path says it in fewer instructions than the compiler finds for it.)
template <bool Wide>
inline void widen(const i8& texels, Fixed8& out) {
    using u8x32 = uint8_t __attribute__((vector_size(32)));
    const u8x32 b = std::bit_cast<u8x32>(texels);
    out = {__builtin_convertvector(__builtin_shufflevector(b, b, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15), u16x16),
           __builtin_convertvector(__builtin_shufflevector(b, b, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31), u16x16)};
}
// Each lane's weight (0..65535) in its texel's four 16-bit lanes.
template <bool Wide>
inline void spread(const i8& weight, Fixed8& out) {
    const u16x16 h = std::bit_cast<u16x16>(weight);  // (lane k's low half is 16-bit lane 2k)
    out = {__builtin_shufflevector(h, h, 0, 0, 0, 0, 2, 2, 2, 2, 4, 4, 4, 4, 6, 6, 6, 6),
           __builtin_shufflevector(h, h, 8, 8, 8, 8, 10, 10, 10, 10, 12, 12, 12, 12, 14, 14, 14, 14)};
}
// Channel k of the eight texels as floats in [0, 1] (unit_of_fixed).
template <bool Wide>
inline void unit_of_fixed8(const Fixed8& v, std::array<f8, 4>& out) {
    auto channel = [&]<int K>() {
        const auto lanes = __builtin_shufflevector(v.lo, v.hi, K, K + 4, K + 8, K + 12, K + 16, K + 20, K + 24, K + 28);
        out[K] = simd::to_float(__builtin_convertvector(lanes, i8)) * Texture::kFixedToUnit;
    };
    channel.template operator()<0>(), channel.template operator()<1>(), channel.template operator()<2>(), channel.template operator()<3>();
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void widen<true>(const i8& texels, Fixed8& out) {
    const __m256i t = __m256i(texels);
    out = {u16x16(_mm256_cvtepu8_epi16(_mm256_castsi256_si128(t))), u16x16(_mm256_cvtepu8_epi16(_mm256_extracti128_si256(t, 1)))};
}
template <>
[[gnu::target("avx2")]] inline void spread<true>(const i8& weight, Fixed8& out) {
    const __m256i w = __m256i(weight), both = _mm256_or_si256(w, _mm256_slli_epi32(w, 16));  // the weight in both halves
    out = {u16x16(_mm256_permutevar8x32_epi32(both, _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3))),
           u16x16(_mm256_permutevar8x32_epi32(both, _mm256_setr_epi32(4, 4, 5, 5, 6, 6, 7, 7)))};
}
template <>
[[gnu::target("avx2")]] inline void unit_of_fixed8<true>(const Fixed8& v, std::array<f8, 4>& out) {
    // As 32-bit lanes, lo is (r, g) and (b, a) of texels 0-3 in turn, hi of texels 4-7.
    const __m256 lo = _mm256_castsi256_ps(__m256i(v.lo)), hi = _mm256_castsi256_ps(__m256i(v.hi));
    const __m256i rg = _mm256_permute4x64_epi64(_mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0x88)), 0xd8);
    const __m256i ba = _mm256_permute4x64_epi64(_mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0xdd)), 0xd8);
    const __m256i low = _mm256_set1_epi32(0xffff);
    const __m256i channel[4] = {_mm256_and_si256(rg, low), _mm256_srli_epi32(rg, 16), _mm256_and_si256(ba, low), _mm256_srli_epi32(ba, 16)};
    for (int k = 0; k < 4; ++k) out[size_t(k)] = f8(_mm256_mul_ps(_mm256_cvtepi32_ps(channel[k]), _mm256_set1_ps(Texture::kFixedToUnit)));
}
#endif

// (a b) >> 16 per 16-bit lane: one instruction on the AVX2 path. (By reference: see gather.)
template <bool Wide>
inline void mul_high(const u16x16& a, const u16x16& b, u16x16& out) {
    for (int k = 0; k < 16; ++k) out[k] = uint16_t((uint32_t(a[k]) * uint32_t(b[k])) >> 16);
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void mul_high<true>(const u16x16& a, const u16x16& b, u16x16& out) {
    out = u16x16(_mm256_mulhi_epu16(__m256i(a), __m256i(b)));
}
#endif

// v0 - (v0 w >> 8) + (v1 w >> 8), w256 = w << 8: the blend of sample_level_fixed and blend_fixed.
template <bool Wide>
inline u16x16 blend16(const u16x16& v0, const u16x16& v1, const u16x16& w256) {
    u16x16 h0, h1;
    mul_high<Wide>(v0, w256, h0);
    mul_high<Wide>(v1, w256, h1);
    return v0 - h0 + h1;
}

// A fixed-point level lookup: the four footprint texels, the weights in 0..255.
template <bool Wide>
inline Fixed8 bilinear16(const i8 (&texels)[4], const i8& fx, const i8& fy) {
    Fixed8 a, b, c, d, wx, wy;
    widen<Wide>(texels[0], a), widen<Wide>(texels[1], b), widen<Wide>(texels[2], c), widen<Wide>(texels[3], d);
    spread<Wide>(fx, wx), spread<Wide>(fy << 8, wy);
    // bottom = 256 a + (b - a) fx: exact, though (b - a) fx wraps around on its own.
    auto row = [](const u16x16& p, const u16x16& q, const u16x16& w) { return u16x16(p << 8) + (q - p) * w; };
    return {blend16<Wide>(row(a.lo, b.lo, wx.lo), row(c.lo, d.lo, wx.lo), wy.lo), blend16<Wide>(row(a.hi, b.hi, wx.hi), row(c.hi, d.hi, wx.hi), wy.hi)};
}

}  // namespace

template <bool Wide, bool Srgb>
void Texture::sample_lanes(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    // Anisotropic filtering compiles to a copy of its own (Aniso), so that it costs the
    // other lookups nothing; so does the fixed-point filter (Fixed, texture.h "Precision").
    auto body = [&]<bool Aniso, bool Fixed, bool Pot>() {
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
                const i8 i = floor_small8(lod);
                const i8 inside = minified & (i >= 0) & (i < last);
                level0 = select(minified & (i >= last), splat_i(last), select(inside, i, splat_i(0)));
                level1 = select(inside, i + 1, level0);
                weight = select(inside, lod - to_float(i), splat(0.0f));
            }
        }
        const bool two_levels = s.mip == MipFilter::Linear && simd::any(weight != 0.0f);
        auto lane_levels = [&](i8 level) {
            LaneLevels r{};
            if (!simd::any(level != level[0])) {  // one level for all (neighbouring quads mostly agree)
                const Level& l = levels_[size_t(level[0])];
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
        // (sRGB textures only: a call here would cost every lookup a call and its spills.)
        const float* decode = Srgb ? srgb::tables().decode.data() : nullptr;
        const bool has_border = s.wrap_s == Wrap::Border || s.wrap_t == Wrap::Border;
        // The footprint's four texels, (ia, ja), (ib, ja), (ia, jb), (ib, jb), from the texel
        // below-left of the sample point, and which are the border color.
        auto footprint = [&](const LaneLevels& l, const i8& i0, const i8& j0, i8 (&texel)[4], i8 (&border)[4]) {
            const i8 ia = wrap_texel8<Pot>(i0, l.width, s.wrap_s), ib = wrap_texel8<Pot>(i0 + 1, l.width, s.wrap_s);
            const i8 ja = wrap_texel8<Pot>(j0, l.height, s.wrap_t), jb = wrap_texel8<Pot>(j0 + 1, l.height, s.wrap_t);
            const i8 is[4] = {ia, ib, ia, ib}, js[4] = {ja, ja, jb, jb};
            for (int t = 0; t < 4; ++t) {
                border[t] = (is[t] < 0) | (js[t] < 0);  // (never without a border wrap mode)
                const i8 index = tile_index8(l, is[t], js[t]);
                gather<Wide>(texels, has_border ? select(border[t], splat_i(0), index) : index, texel[t]);
            }
        };
        // Repeat and clamp read the footprint from the tile's apron (texture.h): its lower-left
        // texel wrapped, the others at offsets 1, 5 and 6. Clamp at an edge, where both texels
        // of an axis are the edge texel, reads the edge texel alone: weight 0 on the other.
        const bool apron = s.wrap_s != Wrap::Mirror && s.wrap_t != Wrap::Mirror;
        auto apron_axis = [&](const i8& i0, const i8& n, Wrap w, i8& fraction) {
            if (w != Wrap::Clamp) return wrap_texel8<Pot>(i0, n, w);
            const i8 edge = (i0 < 0) | (i0 >= n - 1);
            fraction = select(edge, splat_i(0), fraction);
            return select(i0 < 0, splat_i(0), select(edge, n - 1, i0));
        };
        // One level's lookup: in fixed point (sample_level_fixed; a Fixed8 result) ...
        auto at_level_fixed = [&](const LaneLevels& l, const f8& ur, const f8& vr) {
            const i8 x = floor_small8((ur * to_float(l.width) - half) * 256.0f), y = floor_small8((vr * to_float(l.height) - half) * 256.0f);
            i8 fx = select(nearest, splat_i(0), x & 255), fy = select(nearest, splat_i(0), y & 255);
            i8 texel[4];
            if (apron) {
                const i8 i0 = apron_axis(x >> 8, l.width, s.wrap_s, fx), j0 = apron_axis(y >> 8, l.height, s.wrap_t, fy);
                load_footprints<Wide>(texels, tile_index8(l, i0, j0), texel);
            } else {
                i8 border[4];
                footprint(l, x >> 8, y >> 8, texel, border);
            }
            return bilinear16<Wide>(texel, fx, fy);
        };
        // ... or in float (sample_level; four channels).
        auto at_level_float = [&](const LaneLevels& l, const f8& ur, const f8& vr, std::array<f8, 4>& out) {
            const f8 x = ur * to_float(l.width) - half, y = vr * to_float(l.height) - half;
            const i8 i0 = floor_small8(x), j0 = floor_small8(y);
            const f8 fx = select(nearest, splat(0.0f), x - to_float(i0)), fy = select(nearest, splat(0.0f), y - to_float(j0));
            i8 texel[4], border[4];
            footprint(l, i0, j0, texel, border);
            std::array<f8, 4> c[4];
            for (int t = 0; t < 4; ++t)
                for (int k = 0; k < 4; ++k) {
                    f8 value;
                    if (Srgb && k < 3) {  // decoded texel by texel, before the filter
                        const i8 byte = (texel[t] >> (8 * k)) & 255;
                        for (int lane = 0; lane < simd::kLanes; ++lane) value[lane] = decode[size_t(byte[lane])];
                    } else {
                        value = to_float((texel[t] >> (8 * k)) & 255) * (1.0f / 255.0f);
                    }
                    c[t][size_t(k)] = has_border ? select(border[t], splat(s.border[k]), value) : value;
                }
            for (size_t k = 0; k < 4; ++k) {
                const f8 bottom = c[0][k] * (1.0f - fx) + c[1][k] * fx, top = c[2][k] * (1.0f - fx) + c[3][k] * fx;
                out[k] = bottom * (1.0f - fy) + top * fy;
            }
        };
        // The lookup at (ur, vr) in the lanes' level(s), as floats.
        auto lookup_reduced = [&](const LaneLevels& levels0, const LaneLevels& levels1, const f8& ur, const f8& vr, std::array<f8, 4>& out) {
            if constexpr (Fixed) {
                Fixed8 f = at_level_fixed(levels0, ur, vr);
                if (two_levels) {
                    const Fixed8 v1 = at_level_fixed(levels1, ur, vr);
                    Fixed8 w;
                    spread<Wide>(floor_small8(weight * 256.0f) << 8, w);
                    f = {blend16<Wide>(f.lo, v1.lo, w.lo), blend16<Wide>(f.hi, v1.hi, w.hi)};
                }
                unit_of_fixed8<Wide>(f, out);
            } else {
                at_level_float(levels0, ur, vr, out);
                if (two_levels) {
                    std::array<f8, 4> c1;
                    at_level_float(levels1, ur, vr, c1);
                    for (size_t k = 0; k < 4; ++k) out[k] = out[k] + (c1[k] - out[k]) * weight;
                }
            }
        };
        if constexpr (!Aniso) {
            const LaneLevels levels0 = lane_levels(level0);
            return lookup_reduced(levels0, two_levels ? lane_levels(level1) : levels0, reduce8(u, s.wrap_s), reduce8(v, s.wrap_t), rgba);
        }
        // Anisotropic: the same lookup at each probe (sample()'s loop); a lane adds its k-th
        // only while k < its N.
        const LaneLevels levels0 = lane_levels(level0), levels1 = two_levels ? lane_levels(level1) : levels0;
        auto lookup = [&](const f8& pu, const f8& pv, std::array<f8, 4>& out) {
            lookup_reduced(levels0, levels1, reduce8(pu, s.wrap_s), reduce8(pv, s.wrap_t), out);
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
    // And a power-of-two texture's repeat wrap mode (pot_), a mask instead of comparisons.
    auto with_filter = [&]<bool Aniso>() {
        if constexpr (Srgb) {
            body.template operator()<Aniso, false, false>();
        } else if (fixed_point(s)) {
            // (Pot saves 2% on bench_trilinear: not worth another anisotropic copy.)
            if constexpr (!Aniso) {
                if (pot_ && (s.wrap_s == Wrap::Repeat || s.wrap_t == Wrap::Repeat)) return body.template operator()<false, true, true>();
            }
            body.template operator()<Aniso, true, false>();
        } else {
            body.template operator()<Aniso, false, false>();
        }
    };
    if (s.max_anisotropy > 1) with_filter.template operator()<true>();
    else with_filter.template operator()<false>();
}

// In the CPU's best copy (simd.h).
void Texture::sample8(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    simd::on_best_path([&]<bool Wide>() {
        if (srgb_) sample_lanes<Wide, true>(u, v, d, s, rgba);
        else sample_lanes<Wide, false>(u, v, d, s, rgba);
    });
}

}  // namespace softraster
