// The eight-lane lookup (Texture::sample8): select_lod and sample_level_fixed / sample_level of
// texture.cpp, lane by lane the same operations, on eight lanes at once.
#include "softraster/shading/texture.h"

#include <array>
#include <bit>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace softraster {

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

// floor(t) as a float, for |t| < 2^31: to_float(floor_small8(t)), or on the AVX2 path one
// rounding instruction (plus 0, which turns its -0 for -0 into floor_small8's +0). (The
// result by reference: see gather.)
template <bool Wide>
inline void floor8(const f8& t, f8& out) {
    out = simd::to_float(floor_small8(t));
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void floor8<true>(const f8& t, f8& out) {
    out = f8(_mm256_add_ps(_mm256_floor_ps(__m256(t)), _mm256_setzero_ps()));
}
#endif

// detail::reduce on eight lanes (the wrap mode is the same for all).
template <bool Wide>
inline f8 reduce8(f8 u, Wrap w) {
    if (w == Wrap::Repeat || w == Wrap::Mirror) {
        const bool mirror = w == Wrap::Mirror;
        const f8 in = simd::select((u >= -1.0e6f) & (u <= 1.0e6f), u, simd::splat(0.0f));  // (out of range: 0, as reduce)
        f8 whole;
        floor8<Wide>(in * (mirror ? 0.5f : 1.0f), whole);
        return in - (mirror ? 2.0f : 1.0f) * whole;
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
    for (int k = 0; k < simd::kLanes; ++k) {
        int32_t v;
        std::memcpy(&v, p + index[k], sizeof v);  // (p may point at floats: the sRGB table)
        out[k] = v;
    }
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void gather<true>(const uint32_t* p, const i8& index, i8& out) {
    out = i8(_mm256_i32gather_epi32(reinterpret_cast<const int*>(p), __m256i(index), 4));
}
#endif

// A texel vector's channels as floats in [0, 1] (sample_level): r, g, b through the sRGB
// decode table (srgb.h; a gather each) on an sRGB texture, else / 255.
template <bool Wide, bool Srgb>
inline void texel_channels(const i8& texel, const uint32_t* decode, std::array<f8, 4>& c) {
    for (int k = 0; k < 4; ++k) {
        const i8 byte = (texel >> (8 * k)) & 255;
        if (Srgb && k < 3) {
            i8 bits;
            gather<Wide>(decode, byte, bits);
            c[size_t(k)] = std::bit_cast<f8>(bits);
        } else {
            c[size_t(k)] = simd::to_float(byte) * (1.0f / 255.0f);
        }
    }
}
// sample_level's bilinear filter of the footprint's four texels (lower-left, lower-right,
// upper-left, upper-right), in float.
inline void bilinear_float(const std::array<f8, 4> (&c)[4], const f8& fx, const f8& fy, std::array<f8, 4>& out) {
    for (size_t k = 0; k < 4; ++k) {
        const f8 bottom = c[0][k] * (1.0f - fx) + c[1][k] * fx, top = c[2][k] * (1.0f - fx) + c[3][k] * fx;
        out[k] = bottom * (1.0f - fy) + top * fy;
    }
}

// A level's numbers, per lane.
struct LaneLevels {
    i8 width, height, tiles_x, offset;
};

// Texture::texel_index on eight lanes.
// (A level's numbers per lane, or one level's for all.)
template <class N>
inline i8 tile_index8(const N& offset, const N& tiles_x, const i8& i, const i8& j) {
    return offset + ((j >> 2) * tiles_x + (i >> 2)) * Texture::kTileTexels + (j & 3) * Texture::kTileSide + (i & 3);
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
    alignas(32) uint32_t at[simd::kLanes];  // (unsigned: no sign extension per lane)
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

// select_lod on eight lanes, in two steps (anisotropic filtering shortens the footprint
// between them). First the squared lengths of the footprint's x and y axes, in texels of
// level 0 ...
inline void footprint_axes8(const std::array<f8, 4>& d, float w, float h, f8& rx, f8& ry) {
    const f8 ax = d[0] * w, bx = d[1] * h, ay = d[2] * w, by = d[3] * h;
    rx = ax * ax + bx * bx, ry = ay * ay + by * by;
}
// ... then from rho^2 each lane's level or levels, and the second one's weight (minified:
// rho^2 > 1; otherwise level 0 alone).
struct LaneLod {
    i8 level0, level1;
    f8 weight;
};
template <bool Wide>
inline LaneLod lane_lod(const f8& rho2, const i8& minified, MipFilter mip, int last) {
    using simd::select, simd::splat, simd::splat_i, simd::to_float;
    LaneLod r{splat_i(0), splat_i(0), splat(0.0f)};
    const i8 bits = std::bit_cast<i8>(rho2);
    const i8 exponent = ((bits >> 23) & 255) - 127;
    if (mip == MipFilter::Nearest) {
        const i8 l = (exponent + 1) >> 1;
        r.level0 = r.level1 = select(minified, select(l < 0, splat_i(0), select(l > last, splat_i(last), l)), splat_i(0));
    } else if (mip == MipFilter::Linear) {
        const i8 mbits = (bits & 0x007fffff) | 0x3f800000;
        const f8 lod = 0.5f * (to_float(exponent) + (std::bit_cast<f8>(mbits) - 1.0f));
        f8 whole;
        floor8<Wide>(lod, whole);
        const i8 i = simd::to_int(whole);
        const i8 inside = minified & (i >= 0) & (i < last);
        r.level0 = select(minified & (i >= last), splat_i(last), select(inside, i, splat_i(0)));
        r.level1 = select(inside, i + 1, r.level0);
        r.weight = select(inside, lod - to_float(i), splat(0.0f));
    }
    return r;
}

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

// ---- the common lookup
//
// A power-of-two texture repeating on both axes, bilinear both ways, no anisotropy, every lane
// on the same level(s): what real models and the corridor mostly ask for. Linear textures
// filter in fixed point (sample_uniform), sRGB ones in float (sample_uniform_srgb).
// The body of sample_lanes with everything those conditions fix taken out (no level tables,
// no wrap or filter choices per lane, a level's numbers as scalars), and a small function of
// its own (the general body's stack frame and dispatch would cost it a sixth of its time):
// the same operations, the same bits (Texture.UniformLookupsOnPowerOfTwoTexturesEqualOneAtATime).
// False if the lanes' levels differ.
struct PotLevels {
    const uint32_t* texels;
    const int32_t *width, *height, *tiles_x, *offset;  // the first 16 levels' (LevelTables)
    int levels, log2_w, log2_h;
    float w, h;  // level 0's sides
};

// Level k's lookup from level 0's sample point (fu, fv). (The result by reference: see
// gather.)
template <bool Wide>
inline void pot_level(const PotLevels& t, const i8& fu, const i8& fv, int k, Fixed8& out) {
    const i8 x = (fu >> std::min(k, t.log2_w)) - 128, y = (fv >> std::min(k, t.log2_h)) - 128;
    const i8 i0 = (x >> 8) & (t.width[k] - 1), j0 = (y >> 8) & (t.height[k] - 1);
    i8 texel[4];
    load_footprints<Wide>(t.texels, tile_index8(t.offset[k], t.tiles_x[k], i0, j0), texel);
    out = bilinear16<Wide>(texel, x & 255, y & 255);
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void pot_level<true>(const PotLevels& t, const i8& fu, const i8& fv, int k, Fixed8& out) {
    const __m256i x = _mm256_sub_epi32(_mm256_sra_epi32(__m256i(fu), _mm_cvtsi32_si128(std::min(k, t.log2_w))), _mm256_set1_epi32(128));
    const __m256i y = _mm256_sub_epi32(_mm256_sra_epi32(__m256i(fv), _mm_cvtsi32_si128(std::min(k, t.log2_h))), _mm256_set1_epi32(128));
    const __m256i i0 = _mm256_and_si256(_mm256_srai_epi32(x, 8), _mm256_set1_epi32(t.width[k] - 1));
    const __m256i j0 = _mm256_and_si256(_mm256_srai_epi32(y, 8), _mm256_set1_epi32(t.height[k] - 1));
    // tile_index8, as (((j0 / 4) tiles_x + i0 / 4) 5 + j0 % 4) 5 + i0 % 4 + offset
    const __m256i tile = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_srai_epi32(j0, 2), _mm256_set1_epi32(t.tiles_x[k])), _mm256_srai_epi32(i0, 2));
    const __m256i three = _mm256_set1_epi32(3), five = _mm256_set1_epi32(Texture::kTileSide);
    const __m256i row = _mm256_add_epi32(_mm256_mullo_epi32(tile, five), _mm256_and_si256(j0, three));
    const __m256i index = _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(row, five), _mm256_and_si256(i0, three)), _mm256_set1_epi32(t.offset[k]));
    i8 texel[4];
    load_footprints<true>(t.texels, i8(index), texel);
    const __m256i low = _mm256_set1_epi32(255);
    out = bilinear16<true>(texel, i8(_mm256_and_si256(x, low)), i8(_mm256_and_si256(y, low)));
}
#endif

// The level(s) the lanes read, when all read the same: select_lod's, on eight lanes.
struct UniformLevels {
    int level;
    bool two;  // a second level, level + 1, with these weights
    f8 weight;
};
template <bool Wide>
inline bool uniform_levels(const PotLevels& t, const std::array<f8, 4>& d, MipFilter mip, UniformLevels& out) {
    using simd::splat, simd::splat_i;
    LaneLod lod{splat_i(0), splat_i(0), splat(0.0f)};
    if (mip != MipFilter::None) {
        f8 rx, ry;
        footprint_axes8(d, t.w, t.h, rx, ry);
        const f8 rho2 = simd::select(rx > ry, rx, ry);
        lod = lane_lod<Wide>(rho2, rho2 > 1.0f, mip, t.levels - 1);
    }
    out.level = lod.level0[0];
    if (simd::any(lod.level0 != out.level)) return false;
    out.two = simd::any(lod.weight != 0.0f);
    out.weight = lod.weight;
    return out.level + (out.two ? 1 : 0) < 16;  // (past the tables otherwise)
}

// Linear textures: the fixed-point filter (sample_level_fixed).
template <bool Wide>
inline bool sample_uniform(const PotLevels& t, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba) {
    using simd::to_int;
    UniformLevels l;
    if (!uniform_levels<Wide>(t, d, mip, l)) return false;
    // Level 0's sample point in 1/256 texel steps (sample_level_fixed): exact, u being in
    // [0, 1] and the side a power of two, so that truncation is the floor; level k's is it
    // shifted right by k, up to a side of 1.
    const i8 fu = to_int(reduce8<Wide>(u, Wrap::Repeat) * (256.0f * t.w)), fv = to_int(reduce8<Wide>(v, Wrap::Repeat) * (256.0f * t.h));
    auto at_level = [&](int k) {
        Fixed8 f;
        pot_level<Wide>(t, fu, fv, k, f);
        return f;
    };
    Fixed8 f = at_level(l.level);
    if (l.two) {
        const Fixed8 f1 = at_level(l.level + 1);
        Fixed8 w;
        spread<Wide>(to_int(l.weight * 256.0f) << 8, w);  // (weight in [0, 1): truncation is the floor)
        f = {blend16<Wide>(f.lo, f1.lo, w.lo), blend16<Wide>(f.hi, f1.hi, w.hi)};
    }
    unit_of_fixed8<Wide>(f, rgba);
    return true;
}

// sRGB textures: each texel decoded through the table (a gather per channel), then the
// float filter (sample_level), as the general body computes them.
template <bool Wide>
inline void srgb_level(const PotLevels& t, const uint32_t* decode, const f8& ur, const f8& vr, int level, std::array<f8, 4>& out) {
    using simd::to_float;
    const int w = t.width[level], h = t.height[level];
    const f8 x = ur * float(w) - 0.5f, y = vr * float(h) - 0.5f;
    const i8 i0 = floor_small8(x), j0 = floor_small8(y);
    const f8 fx = x - to_float(i0), fy = y - to_float(j0);
    i8 texel[4];
    load_footprints<Wide>(t.texels, tile_index8(t.offset[level], t.tiles_x[level], i0 & (w - 1), j0 & (h - 1)), texel);
    std::array<f8, 4> c[4];
    for (size_t p = 0; p < 4; ++p) texel_channels<Wide, true>(texel[p], decode, c[p]);
    bilinear_float(c, fx, fy, out);
}
template <bool Wide>
inline bool sample_uniform_srgb(const PotLevels& t, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba) {
    UniformLevels l;
    if (!uniform_levels<Wide>(t, d, mip, l)) return false;
    const f8 ur = reduce8<Wide>(u, Wrap::Repeat), vr = reduce8<Wide>(v, Wrap::Repeat);
    const uint32_t* decode = reinterpret_cast<const uint32_t*>(srgb::tables().decode.data());
    srgb_level<Wide>(t, decode, ur, vr, l.level, rgba);
    if (l.two) {
        std::array<f8, 4> c1;
        srgb_level<Wide>(t, decode, ur, vr, l.level + 1, c1);
        for (size_t k = 0; k < 4; ++k) rgba[k] = rgba[k] + (c1[k] - rgba[k]) * l.weight;
    }
    return true;
}

}  // namespace

template <bool Wide, bool Srgb>
void Texture::sample_lanes(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    // Anisotropic filtering compiles to a copy of its own (Aniso), so that it costs the
    // other lookups nothing; so does the fixed-point filter (Fixed, texture.h "Precision").
    auto body = [&]<bool Aniso, bool Fixed, bool Pot>() {
        using simd::select, simd::splat, simd::splat_i, simd::to_float;
        // (Pot: both axes repeat, known here, so that no lookup asks which wrap mode.)
        const Wrap wrap_s = Pot ? Wrap::Repeat : s.wrap_s, wrap_t = Pot ? Wrap::Repeat : s.wrap_t;
        // Which level(s) and filter each lane takes (select_lod).
        i8 level0 = splat_i(0), level1 = splat_i(0), nearest = splat_i(s.mag == Filter::Nearest ? -1 : 0), probes = splat_i(1);
        f8 weight = splat(0.0f), axis_u = splat(0.0f), axis_v = splat(0.0f);
        if (s.uses_lod()) {
            f8 rx, ry;
            footprint_axes8(d, float(width()), float(height()), rx, ry);
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
            const LaneLod lod = lane_lod<Wide>(rho2, minified, s.mip, levels() - 1);
            level0 = lod.level0, level1 = lod.level1, weight = lod.weight;
        }
        const bool two_levels = s.mip == MipFilter::Linear && simd::any(weight != 0.0f);
        auto lane_levels = [&](i8 level) {
            LaneLevels r;  // (not zeroed: every branch sets every number)
            if (!simd::any(level != level[0])) {  // one level for all (neighbouring quads mostly agree)
                const Level& l = levels_[size_t(level[0])];
                r.width = splat_i(l.width), r.height = splat_i(l.height), r.tiles_x = splat_i(l.tiles_x), r.offset = splat_i(l.offset);
                return r;
            }
            if (levels() <= 16) {  // a texture under 65536 texels a side: two table lookups per number
                const i8 high = level >= 8, index = level & 7;
                auto pick = [&](const std::array<int32_t, 16>& table) {
                    i8 low_half, high_half;
                    std::memcpy(&low_half, table.data(), sizeof(i8));
                    std::memcpy(&high_half, table.data() + 8, sizeof(i8));
                    return select(high, simd::permute(high_half, index), simd::permute(low_half, index));
                };
                r.width = pick(tables_.width), r.height = pick(tables_.height), r.tiles_x = pick(tables_.tiles_x), r.offset = pick(tables_.offset);
                return r;
            }
            r.width = r.height = r.tiles_x = r.offset = splat_i(0);
            for (int k = 0; k < simd::kLanes; ++k) {
                const Level& l = levels_[size_t(level[k])];
                r.width[k] = l.width, r.height[k] = l.height, r.tiles_x[k] = l.tiles_x, r.offset[k] = l.offset;
            }
            return r;
        };
        // sample_level: nearest lanes take the bilinear formula at x = u with weights 0, which
        // gives exactly the one texel (t * 1 + t' * 0 = t).
        const f8 half = select(nearest, splat(0.0f), splat(0.5f));
        const i8 half256 = select(nearest, splat_i(0), splat_i(128));  // (the same in 1/256 steps)
        const uint32_t* texels = this->texels();
        // (The table's address once: srgb::tables() is a call.)
        const uint32_t* decode = Srgb ? reinterpret_cast<const uint32_t*>(srgb::tables().decode.data()) : nullptr;
        const bool has_border = wrap_s == Wrap::Border || wrap_t == Wrap::Border;
        // The footprint's four texels, (ia, ja), (ib, ja), (ia, jb), (ib, jb), from the texel
        // below-left of the sample point, and which are the border color.
        auto footprint = [&](const LaneLevels& l, const i8& i0, const i8& j0, i8 (&texel)[4], i8 (&border)[4]) {
            const i8 ia = wrap_texel8<Pot>(i0, l.width, wrap_s), ib = wrap_texel8<Pot>(i0 + 1, l.width, wrap_s);
            const i8 ja = wrap_texel8<Pot>(j0, l.height, wrap_t), jb = wrap_texel8<Pot>(j0 + 1, l.height, wrap_t);
            const i8 is[4] = {ia, ib, ia, ib}, js[4] = {ja, ja, jb, jb};
            for (int t = 0; t < 4; ++t) {
                border[t] = (is[t] < 0) | (js[t] < 0);  // (never without a border wrap mode)
                const i8 index = tile_index8(l.offset, l.tiles_x, is[t], js[t]);
                gather<Wide>(texels, has_border ? select(border[t], splat_i(0), index) : index, texel[t]);
            }
        };
        // Repeat and clamp read the footprint from the tile's apron (texture.h): its lower-left
        // texel wrapped, the others at offsets 1, 5 and 6. Clamp at an edge, where both texels
        // of an axis are the edge texel, reads the edge texel alone: weight 0 on the other.
        const bool apron = wrap_s != Wrap::Mirror && wrap_t != Wrap::Mirror;
        auto apron_axis = [&](const i8& i0, const i8& n, Wrap w, i8& fraction) {
            if (w != Wrap::Clamp) return wrap_texel8<Pot>(i0, n, w);
            const i8 edge = (i0 < 0) | (i0 >= n - 1);
            fraction = select(edge, splat_i(0), fraction);
            return select(i0 < 0, splat_i(0), select(edge, n - 1, i0));
        };
        // One level's lookup: in fixed point (sample_level_fixed; a Fixed8 result) ...
        auto at_level_fixed = [&](const LaneLevels& l, const f8& ur, const f8& vr) {
            // The sample point in 1/256 texel steps (sample_level_fixed; sample_uniform takes
            // a power-of-two texture's from level 0's).
            const i8 x = floor_small8(ur * to_float(l.width) * 256.0f) - half256, y = floor_small8(vr * to_float(l.height) * 256.0f) - half256;
            i8 fx = select(nearest, splat_i(0), x & 255), fy = select(nearest, splat_i(0), y & 255);
            i8 texel[4];
            if (apron) {
                const i8 i0 = apron_axis(x >> 8, l.width, wrap_s, fx), j0 = apron_axis(y >> 8, l.height, wrap_t, fy);
                load_footprints<Wide>(texels, tile_index8(l.offset, l.tiles_x, i0, j0), texel);
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
            for (size_t t = 0; t < 4; ++t) {
                texel_channels<Wide, Srgb>(texel[t], decode, c[t]);
                if (has_border)
                    for (size_t k = 0; k < 4; ++k) c[t][k] = select(border[t], splat(s.border[int(k)]), c[t][k]);
            }
            bilinear_float(c, fx, fy, out);
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
            return lookup_reduced(levels0, two_levels ? lane_levels(level1) : levels0, reduce8<Wide>(u, wrap_s), reduce8<Wide>(v, wrap_t), rgba);
        }
        // Anisotropic: the same lookup at each probe (sample()'s loop); a lane adds its k-th
        // only while k < its N.
        const LaneLevels levels0 = lane_levels(level0), levels1 = two_levels ? lane_levels(level1) : levels0;
        auto lookup = [&](const f8& pu, const f8& pv, std::array<f8, 4>& out) {
            lookup_reduced(levels0, levels1, reduce8<Wide>(pu, wrap_s), reduce8<Wide>(pv, wrap_t), out);
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
                if (pot_ && s.wrap_s == Wrap::Repeat && s.wrap_t == Wrap::Repeat) return body.template operator()<false, true, true>();
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
    // The common lookup first, in a copy of its own (sample_uniform).
    if (pot_ && s.wrap_s == Wrap::Repeat && s.wrap_t == Wrap::Repeat && s.mag == Filter::Bilinear && s.min == Filter::Bilinear && s.max_anisotropy <= 1) {
        const PotLevels t{texels(), tables_.width.data(), tables_.height.data(), tables_.tiles_x.data(), tables_.offset.data(),
                          levels(), std::countr_zero(unsigned(width())), std::countr_zero(unsigned(height())), float(width()), float(height())};
        if (srgb_ ? simd::on_best_path([&]<bool Wide>() { return sample_uniform_srgb<Wide>(t, u, v, d, s.mip, rgba); })
                  : simd::on_best_path([&]<bool Wide>() { return sample_uniform<Wide>(t, u, v, d, s.mip, rgba); }))
            return;
    }
    simd::on_best_path([&]<bool Wide>() {
        if (srgb_) sample_lanes<Wide, true>(u, v, d, s, rgba);
        else sample_lanes<Wide, false>(u, v, d, s, rgba);
    });
}

}  // namespace softraster
