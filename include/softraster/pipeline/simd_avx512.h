// The 512-bit helpers the AVX-512 copies share (the texture lookup's and the sRGB encode's),
// for CPUs whose vector units are that wide (simd::cpu_has_avx512).
#pragma once
#include "softraster/pipeline/simd.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <cstdint>

#include <immintrin.h>

// The AVX-512 copies' instructions (with AVX2's, which they call too).
// A function compiled with these calls only functions compiled with them too (or takes
// scalars and pointers): it passes a vector argument in a register, while a plain function
// (compiled for any x86-64) expects it in memory (the psABI's rule for 32-byte vectors
// without AVX). Inlined, as in Release, the two agree; called, as in the sanitizer build
// (-O0, no flatten), the plain function reads garbage.
#define SOFTRASTER_AVX512_TARGET_NAMES "avx2,fma,avx512f,avx512bw,avx512vl,avx512dq"

namespace softraster::simd::avx512 {

using i64x4 = long long __attribute__((vector_size(32)));
using i32x16 = int32_t __attribute__((vector_size(64)));  // (arithmetic with operators, as simd::i8)
using f32x16 = float __attribute__((vector_size(64)));
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline i32x16 splat(int32_t a) { return i32x16(_mm512_set1_epi32(a)); }
// A register's halves and two halves joined, as vector shuffles: GCC 12's intrinsics for
// these (_mm512_inserti64x4, _mm512_extracti64x4_epi64 and their kind) warn that their own
// placeholder for unused lanes is uninitialized (GCC bug 105593, mended in GCC 13). The same
// instructions.
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m512i join(__m256i low, __m256i high) { return __m512i(__builtin_shufflevector(i64x4(low), i64x4(high), 0, 1, 2, 3, 4, 5, 6, 7)); }
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline f32x16 join(f8 low, f8 high) { return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m256i low_half(__m512i v) { return __m256i(__builtin_shufflevector(v, v, 0, 1, 2, 3)); }
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline __m256i high_half(__m512i v) { return __m256i(__builtin_shufflevector(v, v, 4, 5, 6, 7)); }
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline f8 low_half(f32x16 v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7); }
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline f8 high_half(f32x16 v) { return __builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15); }

}  // namespace softraster::simd::avx512
#endif
