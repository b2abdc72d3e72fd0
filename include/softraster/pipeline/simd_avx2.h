// The AVX2 helpers that more than one stage's eight-lane code shares. (simd.h keeps to the
// vector extensions; these are where records in memory turn into lanes and back.)
#pragma once
#include "softraster/pipeline/simd.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <algorithm>
#include <cstddef>

#include <immintrin.h>

namespace softraster::simd {

// Eight records of four 32-bit fields, records k and k + 4 in the two 128-bit halves of
// r[k], become four eight-lane vectors, r[f] holding field f of records 0-7 in lane order: a
// 4x4 transpose in each half. It is its own inverse (lanes back to records). Vertex
// processing reads vertices and clip positions and writes varyings and window positions this
// way (load_columns, store_columns below), binning reads triangle corners, the texture lookup
// a bilinear footprint's four texels.
[[gnu::target("avx2")]] inline void transpose4x4_halves(__m256i (&r)[4]) {
    const __m256i t0 = _mm256_unpacklo_epi32(r[0], r[1]), t1 = _mm256_unpackhi_epi32(r[0], r[1]);
    const __m256i t2 = _mm256_unpacklo_epi32(r[2], r[3]), t3 = _mm256_unpackhi_epi32(r[2], r[3]);
    r[0] = _mm256_unpacklo_epi64(t0, t2), r[1] = _mm256_unpackhi_epi64(t0, t2);
    r[2] = _mm256_unpacklo_epi64(t1, t3), r[3] = _mm256_unpackhi_epi64(t1, t3);
}

// Fields f to f + 3 of eight records `stride` bytes apart (the first at `at`), as four
// vectors: eight 16-byte loads and the transpose above. (Each load reads all four fields: the
// records must have them.)
[[gnu::target("avx2")]] inline void load_columns(const void* at, size_t stride, f8 (&out)[4]) {
    const char* p = static_cast<const char*>(at);
    __m256i r[4];
    for (size_t k = 0; k < 4; ++k)
        r[k] = _mm256_castps_si256(_mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(reinterpret_cast<const float*>(p + k * stride))),
                                                        _mm_loadu_ps(reinterpret_cast<const float*>(p + (k + 4) * stride)), 1));
    transpose4x4_halves(r);
    for (size_t f = 0; f < 4; ++f) out[f] = f8(_mm256_castsi256_ps(r[f]));
}
// The other way: the lanes of vectors in[0..count) (count 1 to 4) into that many consecutive
// floats of eight records `stride` bytes apart, writing nothing else.
[[gnu::target("avx2")]] inline void store_columns(const f8* in, int count, void* at, size_t stride) {
    char* p = static_cast<char*>(at);
    __m256i r[4];
    for (int f = 0; f < 4; ++f) r[f] = _mm256_castps_si256(__m256(in[std::min(f, count - 1)]));  // (fields past count: not stored)
    transpose4x4_halves(r);
    for (size_t k = 0; k < 8; ++k) {
        const __m128i row = k < 4 ? _mm256_castsi256_si128(r[k]) : _mm256_extracti128_si256(r[k - 4], 1);
        char* q = p + k * stride;
        if (count == 4) _mm_storeu_si128(reinterpret_cast<__m128i*>(q), row);
        else if (count >= 2) _mm_storel_epi64(reinterpret_cast<__m128i*>(q), row);
        if (count == 3) _mm_store_ss(reinterpret_cast<float*>(q + 8), _mm_castsi128_ps(_mm_unpackhi_epi64(row, row)));
        if (count == 1) _mm_store_ss(reinterpret_cast<float*>(q), _mm_castsi128_ps(row));
    }
}

}  // namespace softraster::simd
#endif
