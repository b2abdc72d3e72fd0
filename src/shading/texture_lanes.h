// The eight-lane lookup's arithmetic (Texture::sample8), shared by its two files:
// texture_lanes.cpp (any texture and sampler) and texture_uniform.cpp (the common case).
// select_lod and sample_level_fixed / sample_level of texture.cpp, lane by lane the same
// operations in the same order (so the bits agree with sample()), on eight lanes at once.
#pragma once
#include <array>
#include <bit>
#include <cstring>

#include "softraster/shading/texture.h"
#include "softraster/pipeline/simd_avx2.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace softraster::lanes {

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

// sample()'s blend of two levels' colors in float: c0 + (c1 - c0) w.
inline void blend_levels_float(std::array<f8, 4>& c0, const std::array<f8, 4>& c1, const f8& w) {
    for (size_t k = 0; k < 4; ++k) c0[k] = c0[k] + (c1[k] - c0[k]) * w;
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
// One 32-byte load per lane holds its whole footprint: (a, b) are texels 0 and 1 of the load,
// (c, d) texels 5 and 6, one tile row (5) on. A permute gathers the four, lanes k and k + 4
// share a register, and simd::transpose4x4_halves turns the four registers into the
// footprint's texels across the lanes: half the loads of one per row, and far cheaper here than
// four gathers (docs/performance.md, "One load per footprint"). The load reads 8 texels from
// the footprint's first; the array has slack for it after its end (texture.cpp).
template <>
[[gnu::target("avx2")]] inline void load_footprints<true>(const uint32_t* p, const i8& index, i8 (&texel)[4]) {
    constexpr int kRow = Texture::kTileSide;
    static_assert(kRow + 1 < 8, "both rows of a footprint within one 32-byte load");
    alignas(32) uint32_t at[simd::kLanes];  // (unsigned: no sign extension per lane)
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), __m256i(index));
    const __m256i abcd = _mm256_setr_epi32(0, 1, kRow, kRow + 1, 0, 1, kRow, kRow + 1);
    __m256i y[4];
    for (int k = 0; k < 4; ++k) {  // (a loop, not a lambda: a lambda here would not be compiled for AVX2)
        const __m256i low = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + at[k])), abcd);
        const __m256i high = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + at[k + 4])), abcd);
        y[k] = _mm256_blend_epi32(low, high, 0xf0);
    }
    simd::transpose4x4_halves(y);
    for (int k = 0; k < 4; ++k) texel[k] = i8(y[k]);
}
#endif

// select_lod on eight lanes, in two steps (anisotropic filtering shortens the footprint
// between them). First the squared lengths of the footprint's x and y axes, in texels of
// level 0 ...
// (d: du/dx, dv/dx, du/dy, dv/dy, four vectors in a row.)
inline void footprint_axes8(const f8* d, float w, float h, f8& rx, f8& ry) {
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
// One gather's eight texels make two registers of sixteen 16-bit lanes, each texel's r, g,
// b, a in four lanes: texels 0, 1, 4, 5 in `lo`, 2, 3, 6, 7 in `hi`. (That order keeps each
// texel in its 128-bit half, where AVX2 widens bytes with one single-cycle unpack; texels
// 0-3 and 4-7 would each take a two-operation widening across the halves.) A blend then
// works on two texels' channels at once, sixteen at a time, instead of eight float lanes per
// channel.
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
    out = {__builtin_convertvector(__builtin_shufflevector(b, b, 0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23), u16x16),
           __builtin_convertvector(__builtin_shufflevector(b, b, 8, 9, 10, 11, 12, 13, 14, 15, 24, 25, 26, 27, 28, 29, 30, 31), u16x16)};
}
// Each lane's weight (0..65535) in its texel's four 16-bit lanes.
template <bool Wide>
inline void spread(const i8& weight, Fixed8& out) {
    const u16x16 h = std::bit_cast<u16x16>(weight);  // (lane k's low half is 16-bit lane 2k)
    out = {__builtin_shufflevector(h, h, 0, 0, 0, 0, 2, 2, 2, 2, 8, 8, 8, 8, 10, 10, 10, 10),
           __builtin_shufflevector(h, h, 4, 4, 4, 4, 6, 6, 6, 6, 12, 12, 12, 12, 14, 14, 14, 14)};
}
// Channel k of the eight texels as floats in [0, 1] (unit_of_fixed).
template <bool Wide>
inline void unit_of_fixed8(const Fixed8& v, std::array<f8, 4>& out) {
    auto channel = [&]<int K>() {
        const auto lanes = __builtin_shufflevector(v.lo, v.hi, K, K + 4, K + 16, K + 20, K + 8, K + 12, K + 24, K + 28);
        out[K] = simd::to_float(__builtin_convertvector(lanes, i8)) * Texture::kFixedToUnit;
    };
    channel.template operator()<0>(), channel.template operator()<1>(), channel.template operator()<2>(), channel.template operator()<3>();
}
#if SOFTRASTER_HAS_AVX2_PATH
template <>
[[gnu::target("avx2")]] inline void widen<true>(const i8& texels, Fixed8& out) {
    const __m256i t = __m256i(texels), zero = _mm256_setzero_si256();
    out = {u16x16(_mm256_unpacklo_epi8(t, zero)), u16x16(_mm256_unpackhi_epi8(t, zero))};
}
template <>
[[gnu::target("avx2")]] inline void spread<true>(const i8& weight, Fixed8& out) {
    const __m256i w = __m256i(weight), both = _mm256_or_si256(w, _mm256_slli_epi32(w, 16));  // the weight in both halves
    out = {u16x16(_mm256_permutevar8x32_epi32(both, _mm256_setr_epi32(0, 0, 1, 1, 4, 4, 5, 5))),
           u16x16(_mm256_permutevar8x32_epi32(both, _mm256_setr_epi32(2, 2, 3, 3, 6, 6, 7, 7)))};
}
template <>
[[gnu::target("avx2")]] inline void unit_of_fixed8<true>(const Fixed8& v, std::array<f8, 4>& out) {
    // As 32-bit lanes, each half of lo is (r, g) and (b, a) of two texels in turn (0, 1 and
    // 4, 5), of hi the next two (2, 3 and 6, 7): picking the even and the odd lanes of both
    // gives every texel's (r, g) and (b, a) in order.
    const __m256 lo = _mm256_castsi256_ps(__m256i(v.lo)), hi = _mm256_castsi256_ps(__m256i(v.hi));
    const __m256i rg = _mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0x88)), ba = _mm256_castps_si256(_mm256_shuffle_ps(lo, hi, 0xdd));
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

// v0 - (v0 w >> n) + (v1 w >> n), w256 = w << (16 - n): the blend of sample_level_fixed and
// blend_fixed (n = 8 but for sRGB textures, 12).
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

// ---- an sRGB texture's texels, already on the fixed-point scale (Texture::fixed_texels)
//
// Each texel is four 16-bit values, eight bytes: a lane's texel goes to its place in Fixed8
// (lane l in lo for l = 0, 1, 4, 5, in hi for 2, 3, 6, 7) with no widening.
inline void put_fixed(Fixed8& out, int lane, uint64_t texel) {
    u16x16& half = (lane & 2) ? out.hi : out.lo;
    const int at = 4 * ((lane & 1) + ((lane & 4) >> 1));
    for (int c = 0; c < 4; ++c) half[at + c] = uint16_t(texel >> (16 * c));
}
// The four texels of each lane's footprint in the apron layout (load_footprints).
template <bool Wide>
inline void load_footprints_fixed(const uint64_t* p, const i8& index, Fixed8 (&corner)[4]) {
    for (int k = 0; k < simd::kLanes; ++k) {
        const uint64_t* t = p + uint32_t(index[k]);
        put_fixed(corner[0], k, t[0]), put_fixed(corner[1], k, t[1]);
        put_fixed(corner[2], k, t[Texture::kTileSide]), put_fixed(corner[3], k, t[Texture::kTileSide + 1]);
    }
}
// One texel per lane, anywhere (the footprints of mirrored repeat).
template <bool Wide>
inline void gather_fixed(const uint64_t* p, const i8& index, Fixed8& out) {
    for (int k = 0; k < simd::kLanes; ++k) put_fixed(out, k, p[uint32_t(index[k])]);
}
#if SOFTRASTER_HAS_AVX2_PATH
// A lane's two 16-byte rows of its footprint, (a, b) and (c, d); lanes k and k + 4 share a
// register, and one unpack of two such registers gives a corner's texels in Fixed8's order.
[[gnu::target("avx2")]] inline __m256i two_texels_of_two_lanes(const uint64_t* low, const uint64_t* high) {
    return _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(low))),
                                   _mm_loadu_si128(reinterpret_cast<const __m128i*>(high)), 1);
}
template <>
[[gnu::target("avx2")]] inline void load_footprints_fixed<true>(const uint64_t* p, const i8& index, Fixed8 (&corner)[4]) {
    alignas(32) uint32_t at[simd::kLanes];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), __m256i(index));
    for (int row = 0; row < 2; ++row) {  // [a b] (row 0) or [c d] (row 1) of lanes k and k + 4
        const uint64_t* q = p + row * Texture::kTileSide;
        const __m256i l0 = two_texels_of_two_lanes(q + at[0], q + at[4]), l1 = two_texels_of_two_lanes(q + at[1], q + at[5]);
        const __m256i l2 = two_texels_of_two_lanes(q + at[2], q + at[6]), l3 = two_texels_of_two_lanes(q + at[3], q + at[7]);
        corner[2 * row] = {u16x16(_mm256_unpacklo_epi64(l0, l1)), u16x16(_mm256_unpacklo_epi64(l2, l3))};
        corner[2 * row + 1] = {u16x16(_mm256_unpackhi_epi64(l0, l1)), u16x16(_mm256_unpackhi_epi64(l2, l3))};
    }
}
template <>
[[gnu::target("avx2")]] inline void gather_fixed<true>(const uint64_t* p, const i8& index, Fixed8& out) {
    const __m256i i = __m256i(index);
    const __m128i lo = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(i, _mm256_setr_epi32(0, 1, 4, 5, 0, 0, 0, 0)));
    const __m128i hi = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(i, _mm256_setr_epi32(2, 3, 6, 7, 0, 0, 0, 0)));
    const long long* base = reinterpret_cast<const long long*>(p);
    out = {u16x16(_mm256_i32gather_epi64(base, lo, 8)), u16x16(_mm256_i32gather_epi64(base, hi, 8))};
}
#endif
// A fixed-point level lookup from texels on the fixed-point scale, weights of Bits bits
// (sample_level_fixed's rows as its columns: p - (p w >> Bits) + (q w >> Bits)).
template <bool Wide, int Bits>
inline Fixed8 bilinear_fixed(const Fixed8 (&c)[4], const i8& fx, const i8& fy) {
    Fixed8 wx, wy;
    spread<Wide>(fx << (16 - Bits), wx), spread<Wide>(fy << (16 - Bits), wy);
    return {blend16<Wide>(blend16<Wide>(c[0].lo, c[1].lo, wx.lo), blend16<Wide>(c[2].lo, c[3].lo, wx.lo), wy.lo),
            blend16<Wide>(blend16<Wide>(c[0].hi, c[1].hi, wx.hi), blend16<Wide>(c[2].hi, c[3].hi, wx.hi), wy.hi)};
}

// The common lookup (texture_uniform.cpp): a power-of-two texture repeating on both axes,
// bilinear both ways, no anisotropy, every lane on the same level(s) or on one of two
// neighbouring first levels, in the CPU's best copy, in fixed point. The texture's numbers
// it reads: the first 16 levels' (LevelTables), level 0's sides, and its texels, an sRGB
// texture's decoded (Texture::fixed_texels).
struct PotLevels {
    const uint32_t* texels;
    const uint64_t* fixed_texels;  // an sRGB texture's; null for a linear one
    const LevelTables* tables;
    int levels;
    float w, h;
};
// One group's lookups: false (rgba untouched) if its lanes' first levels differ by more than one.
bool sample_uniform(const PotLevels& t, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba);
// Two groups' lookups (Texture::sample_pair): false (rgba untouched) unless all sixteen
// lanes' first levels are within one of each other.
bool sample_uniform_pair(const PotLevels& t, const f8& u0, const f8& v0, const f8& u1, const f8& v1, const std::array<f8, 4>& d0,
                         const std::array<f8, 4>& d1, MipFilter mip, std::array<f8, 4>& rgba0, std::array<f8, 4>& rgba1);
// Four groups' lookups (Texture::sample_four): false (rgba untouched) unless all 32 lanes'
// first levels are within one of each other. (Where groups 0 and 1 have the same
// derivatives, and 2 and 3 too, each pair takes one level of detail.)
bool sample_uniform_four(const PotLevels& t, const f8* const (&uv)[4], MipFilter mip, std::array<f8, 4> (&rgba)[4]);

}  // namespace softraster::lanes
