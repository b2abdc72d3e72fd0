// The common lookup's steps on 512-bit registers (its AVX-512 copy, texture_uniform.cpp), for
// CPUs whose vector units are that wide (simd::cpu_has_avx512). Each step computes what its
// AVX2 counterpart in texture_lanes.h computes, bit for bit; only the register layout
// differs. A 512-bit register holds eight texels of 16-bit channels in lane order, texel t's
// r, g, b, a in 16-bit lanes 4t to 4t + 3 (no lo/hi halves as in Fixed8): one widening
// instruction makes it from eight 8-bit texels, and each blend of the filter is one
// instruction on all 32 values where the AVX2 copy takes two.
#pragma once
#include "texture_lanes.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include "softraster/pipeline/simd_avx512.h"

namespace softraster::lanes::avx512 {

using simd::avx512::f32x16, simd::avx512::i32x16, simd::avx512::splat, simd::avx512::join, simd::avx512::low_half, simd::avx512::high_half;

// The four texels of each lane's bilinear footprint (load_footprints<true>): one 32-byte
// load per lane as there, two lanes' loads to a register, and two rounds of two-register
// permutes in place of the AVX2 copy's permutes, blends and transpose: the first puts lanes
// 0, 1, 4, 5 (and 2, 3, 6, 7) corner by corner, the second all eight lanes of corners a and
// b, and of c and d.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline void load_footprints(const uint32_t* p, const i8& index, i8 (&texel)[4]) {
    constexpr int kRow = Texture::kTileSide;  // (a at 0, b at 1, c at kRow, d at kRow + 1 of each lane's load)
    alignas(32) uint32_t at[simd::kLanes];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), __m256i(index));
    __m512i lanes[4];  // [k]: lanes k and k + 4
    for (int k = 0; k < 4; ++k)
        lanes[k] = join(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + at[k])), _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + at[k + 4])));
    // Of lanes[0] (indices 0-15) and lanes[1] (16-31): a of lanes 0, 1, 4, 5, then b, c, d.
    const __m512i corners = _mm512_setr_epi32(0, 16, 8, 24, 1, 17, 9, 25, kRow, 16 + kRow, 8 + kRow, 24 + kRow, kRow + 1, 17 + kRow, 9 + kRow, 25 + kRow);
    const __m512i l0145 = _mm512_permutex2var_epi32(lanes[0], corners, lanes[1]), l2367 = _mm512_permutex2var_epi32(lanes[2], corners, lanes[3]);
    const __m512i ab = _mm512_permutex2var_epi32(l0145, _mm512_setr_epi32(0, 1, 16, 17, 2, 3, 18, 19, 4, 5, 20, 21, 6, 7, 22, 23), l2367);
    const __m512i cd = _mm512_permutex2var_epi32(l0145, _mm512_setr_epi32(8, 9, 24, 25, 10, 11, 26, 27, 12, 13, 28, 29, 14, 15, 30, 31), l2367);
    texel[0] = i8(low_half(ab)), texel[1] = i8(high_half(ab)), texel[2] = i8(low_half(cd)), texel[3] = i8(high_half(cd));
}

// The same for an sRGB texture's decoded texels (load_footprints_fixed<true>): each lane's
// two 16-byte rows, four lanes' rows to a register, and one two-register permute per corner.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i two_texels_of_four_lanes(const uint64_t* q, const uint32_t* at) {
    auto row = [&](int k) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(q + at[k])); };
    // (The first row in all four places, then each other row in its own: a load and three
    // inserts that take their rows from memory; a broadcast zero-masked with all lanes kept
    // is the plain broadcast, whose own intrinsic warns as above.)
    const __m512i first = _mm512_maskz_broadcast_i32x4(0xffff, row(0));
    return _mm512_inserti32x4(_mm512_inserti32x4(_mm512_inserti32x4(first, row(1), 1), row(2), 2), row(3), 3);
}
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline void load_footprints_fixed(const uint64_t* p, const i8& index, __m512i (&corner)[4]) {
    alignas(32) uint32_t at[simd::kLanes];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), __m256i(index));
    const __m512i first = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), second = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
    for (int row = 0; row < 2; ++row) {  // [a b] (row 0) or [c d] (row 1) of lanes 0-3, then of lanes 4-7
        const uint64_t* q = p + row * Texture::kTileSide;
        const __m512i lanes0123 = two_texels_of_four_lanes(q, at), lanes4567 = two_texels_of_four_lanes(q, at + 4);
        corner[2 * row] = _mm512_permutex2var_epi64(lanes0123, first, lanes4567);
        corner[2 * row + 1] = _mm512_permutex2var_epi64(lanes0123, second, lanes4567);
    }
}

// Each lane's weight (its low 16 bits) in its texel's four 16-bit lanes (spread).
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i spread(const i8& weight) {
    const __m512i low_halves = _mm512_set_epi16(14, 14, 14, 14, 12, 12, 12, 12, 10, 10, 10, 10, 8, 8, 8, 8, 6, 6, 6, 6, 4, 4, 4, 4, 2, 2, 2, 2, 0, 0, 0, 0);
    return _mm512_permutexvar_epi16(low_halves, join(__m256i(weight), __m256i(weight)));
}
// v0 - (v0 w >> 16) + (v1 w >> 16) per 16-bit lane (blend16).
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i blend(__m512i v0, __m512i v1, __m512i w) {
    return _mm512_add_epi16(_mm512_sub_epi16(v0, _mm512_mulhi_epu16(v0, w)), _mm512_mulhi_epu16(v1, w));
}
// 256 p + (q - p) w per 16-bit lane (bilinear16's rows).
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i row_blend(__m512i p, __m512i q, __m512i w) {
    return _mm512_add_epi16(_mm512_slli_epi16(p, 8), _mm512_mullo_epi16(_mm512_sub_epi16(q, p), w));
}
// A linear texture's level lookup (bilinear16): the footprint's 8-bit texels, weights 0..255.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i bilinear16(const i8 (&texels)[4], const i8& fx, const i8& fy) {
    __m512i c[4];
    for (int k = 0; k < 4; ++k) c[k] = _mm512_cvtepu8_epi16(__m256i(texels[k]));
    const __m512i wx = spread(fx), wy = spread(fy << 8);
    return blend(row_blend(c[0], c[1], wx), row_blend(c[2], c[3], wx), wy);
}
// An sRGB texture's (bilinear_fixed): texels on the fixed-point scale, weights of Bits bits.
template <int Bits>
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i bilinear_fixed(const __m512i (&c)[4], const i8& fx, const i8& fy) {
    const __m512i wx = spread(fx << (16 - Bits)), wy = spread(fy << (16 - Bits));
    return blend(blend(c[0], c[1], wx), blend(c[2], c[3], wx), wy);
}
// Sixteen 16-bit values as floats in [0, 1] (unit_of_fixed).
// (The zero-masked conversions: the plain ones warn as above, and GCC splits the vector
// conversions into 256-bit halves.)
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline f32x16 unit_floats(__m256i values) {
    return f32x16(_mm512_maskz_cvtepi32_ps(0xffff, _mm512_maskz_cvtepu16_epi32(0xffff, values))) * Texture::kFixedToUnit;
}
// The eight texels' channels as floats in [0, 1] (unit_of_fixed8): one permute sorts the 32
// values by channel, and each half widens to two channels' 32-bit lanes.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline void unit_of_fixed(__m512i v, std::array<f8, 4>& out) {
    const __m512i by_channel = _mm512_set_epi16(31, 27, 23, 19, 15, 11, 7, 3, 30, 26, 22, 18, 14, 10, 6, 2, 29, 25, 21, 17, 13, 9, 5, 1, 28, 24, 20, 16, 12, 8, 4, 0);
    const __m512i sorted = _mm512_permutexvar_epi16(by_channel, v);
    const f32x16 rg = unit_floats(low_half(sorted)), ba = unit_floats(high_half(sorted));
    out[0] = low_half(rg), out[1] = high_half(rg), out[2] = low_half(ba), out[3] = high_half(ba);
}

}  // namespace softraster::lanes::avx512
#endif
