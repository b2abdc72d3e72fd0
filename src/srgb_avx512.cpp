// sRGB's exact encode on 512-bit registers (srgb_avx512.h): an approximation, and the
// table's exact encode (srgb.h) only where the approximation cannot decide.
//
// The stored value of l in [0, 1] is the number of thresholds t_k = decode((k - 1/2) / 255)
// that l reaches, and l >= t_k exactly when Y(l) = 255 E(l) + 1/2 >= k, E being decode's
// inverse:
//   E(l) = 12.92 l                      for l <= 0.04045 / 12.92 (= 0.0031308...)
//        = 1.055 l^(5/12) - 0.055       above
// so the stored value is floor(Y(l)). Below, y approximates Y; where y is at least
// kUndecided = 2e-4 from the nearest integer, floor(y) = floor(Y), and the other values,
// about one in 2,500, are encoded one at a time with the table. Over every float in [0, 1] y
// is within 8e-5 of Y: with kUndecided at 8e-5 the test Srgb.SixteenLanesEncodeEveryFloatExactly,
// which checks every float, passes, at 4e-5 it fails. The table's encode gathers one entry
// per lane (srgb::encode_avx2), and a gather of eight lanes takes some 12 cycles on the CPUs
// measured; the approximation's 20 instructions cover sixteen lanes (docs/performance.md,
// "The sRGB encode without a table").
//
// The power: with l = 2^e m, m in [0.75, 1.5), l^(5/12) = 2^(5e/12) m^(5/12). 2^(5e/12) comes from a table of
// the eight octaves the power's part of [0, 1] spans (one permute), and 255 * 1.055 *
// m^(5/12) is a polynomial of degree 6 in m - 1 (a least-squares fit on Chebyshev points,
// scripts/fit-srgb-encode.py).
#include "softraster/srgb_avx512.h"

#include <bit>
#include <cmath>

#include "softraster/pipeline/simd_avx512.h"
#include "softraster/srgb.h"

#if SOFTRASTER_HAS_AVX2_PATH
namespace softraster::srgb {
namespace {

using simd::avx512::f32x16;

// Every lane: the zero-masked forms of the instructions whose plain intrinsics warn under
// GCC 12 (GCC bug 105593, simd_avx512.h) are the same instructions.
constexpr __mmask16 kAll = 0xffff;
constexpr float kUndecided = 2e-4f;
constexpr float kLinearUpTo = 0.04045f / 12.92f;
// 255 * 1.055 * m^(5/12) = sum c_i (m - 1)^i on [0.75, 1.5] (scripts/fit-srgb-encode.py).
constexpr float kPower[7] = {269.024963f, 112.093201f, -32.686451f, 17.2804279f, -11.4138174f, 8.02663898f, -3.67988682f};
// 2^(5e/12) for e = -8..-1 at [e + 8], and 1 for the octave e = 0 ([0.75, 1)). Lanes of the
// linear part (e < -8) read some entry; their result is not used.
const std::array<float, 16> kOctaveScale = [] {
    std::array<float, 16> s{};
    for (int i = 0; i < 16; ++i) s[size_t(i)] = i < 8 ? float(std::exp2(5.0 * (i - 8) / 12.0)) : 1.0f;
    return s;
}();

// Sixteen lanes' stored values, and in `undecided` the lanes left to the table.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i encode16(__m512 x, __mmask16& undecided) {
    // (max(x, 0) takes the second operand, 0, for a NaN; below 1 keeps every lane in an
    // octave of the table, and 1's Y, 255.5, is the largest float's below it within 1e-4.)
    const __m512 l = _mm512_maskz_min_ps(kAll, _mm512_maskz_max_ps(kAll, x, _mm512_setzero_ps()), _mm512_set1_ps(std::nextafter(1.0f, 0.0f)));
    // The octave e (as e + 8, the table's index) from the exponent field of l over 0.75's,
    // and m, which VGETMANTPS normalizes to [0.75, 1.5) in the same octave.
    const __m512i bits = _mm512_castps_si512(l);
    const __m512i e8 = _mm512_maskz_srai_epi32(kAll, _mm512_sub_epi32(bits, _mm512_set1_epi32(int32_t(std::bit_cast<uint32_t>(0.75f) - (8u << 23)))), 23);
    const __m512 m1 = _mm512_sub_ps(_mm512_maskz_getmant_ps(kAll, l, _MM_MANT_NORM_p75_1p5, _MM_MANT_SIGN_src), _mm512_set1_ps(1.0f));
    const __m512 scale = _mm512_maskz_permutexvar_ps(kAll, e8, _mm512_loadu_ps(kOctaveScale.data()));
    __m512 p = _mm512_set1_ps(kPower[6]);
    for (int i = 5; i >= 0; --i) p = _mm512_fmadd_ps(p, m1, _mm512_set1_ps(kPower[i]));
    const __m512 power = _mm512_fmadd_ps(scale, p, _mm512_set1_ps(0.5f - 255.0f * 0.055f));
    const __m512 linear = _mm512_fmadd_ps(l, _mm512_set1_ps(255.0f * 12.92f), _mm512_set1_ps(0.5f));
    const __m512 y = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(l, _mm512_set1_ps(kLinearUpTo), _CMP_LE_OQ), power, linear);
    // y - round(y) (VREDUCEPS), and its size.
    const __m512 off = _mm512_reduce_ps(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    undecided = _mm512_cmp_ps_mask(_mm512_abs_ps(off), _mm512_set1_ps(kUndecided), _CMP_LT_OQ);
    return _mm512_maskz_cvttps_epi32(kAll, y);  // (y >= 0.5: truncation is the floor)
}

// The lanes of x (one channel of two groups) left undecided, from the table.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i decide(const Tables& t, f32x16 x, __m512i k, __mmask16 undecided) {
    alignas(64) int32_t stored[16];
    _mm512_store_si512(stored, k);
    for (unsigned lanes = undecided; lanes; lanes &= lanes - 1) {
        const int lane = std::countr_zero(lanes);
        stored[lane] = encode(t, x[lane]);
    }
    return _mm512_load_si512(stored);
}

}  // namespace

[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] void pack_groups_avx512(const std::array<simd::f8, 4>* rgba, int count, simd::i8* out) {
    using simd::avx512::join, simd::avx512::low_half, simd::avx512::high_half;
    const Tables& t = tables();
    for (int g = 0; g < count; g += 2) {
        const std::array<simd::f8, 4>& first = rgba[g];
        const std::array<simd::f8, 4>& second = g + 1 < count ? rgba[g + 1] : rgba[g];  // (an odd last group twice)
        f32x16 c[3];
        __m512i k[3];
        __mmask16 undecided[3];
        for (int i = 0; i < 3; ++i) c[i] = join(first[size_t(i)], second[size_t(i)]), k[i] = encode16(__m512(c[i]), undecided[i]);
        // (One test for the three channels: a branch after each would hold the next
        // channel's work back until the previous one's chain is done.)
        if (undecided[0] | undecided[1] | undecided[2]) [[unlikely]]
            for (int i = 0; i < 3; ++i) k[i] = decide(t, c[i], k[i], undecided[i]);
        // Alpha as quantize_unorm8: clamped (a NaN to 0), times 255, plus 1/2, truncated.
        // (Not a call of it: see simd_avx512.h on calling plain functions from these.)
        const __m512 a = __m512(join(first[3], second[3]));
        const __m512 a01 = _mm512_maskz_min_ps(kAll, _mm512_maskz_max_ps(kAll, a, _mm512_setzero_ps()), _mm512_set1_ps(1.0f));
        const __m512i qa = _mm512_maskz_cvttps_epi32(kAll, _mm512_add_ps(_mm512_mul_ps(a01, _mm512_set1_ps(255.0f)), _mm512_set1_ps(0.5f)));
        const __m512i packed = _mm512_or_si512(_mm512_or_si512(k[0], _mm512_maskz_slli_epi32(kAll, k[1], 8)), _mm512_or_si512(_mm512_maskz_slli_epi32(kAll, k[2], 16), _mm512_maskz_slli_epi32(kAll, qa, 24)));
        out[g] = simd::i8(low_half(packed));
        if (g + 1 < count) out[g + 1] = simd::i8(high_half(packed));
    }
}

}  // namespace softraster::srgb
#endif
