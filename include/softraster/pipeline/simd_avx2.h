// The AVX2 helpers that more than one stage's eight-lane code shares. (simd.h keeps to the
// vector extensions; these are where records in memory turn into lanes and back.)
#pragma once
#include "softraster/pipeline/simd.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <immintrin.h>

namespace softraster::simd {

// Eight records of four 32-bit fields, records k and k + 4 in the two 128-bit halves of
// r[k], become four eight-lane vectors, r[f] holding field f of records 0-7 in lane order: a
// 4x4 transpose in each half. It is its own inverse (lanes back to records). Vertex
// processing reads clip positions and writes window positions this way, binning reads
// triangle corners, the texture lookup a bilinear footprint's four texels.
[[gnu::target("avx2")]] inline void transpose4x4_halves(__m256i (&r)[4]) {
    const __m256i t0 = _mm256_unpacklo_epi32(r[0], r[1]), t1 = _mm256_unpackhi_epi32(r[0], r[1]);
    const __m256i t2 = _mm256_unpacklo_epi32(r[2], r[3]), t3 = _mm256_unpackhi_epi32(r[2], r[3]);
    r[0] = _mm256_unpacklo_epi64(t0, t2), r[1] = _mm256_unpackhi_epi64(t0, t2);
    r[2] = _mm256_unpacklo_epi64(t1, t3), r[3] = _mm256_unpackhi_epi64(t1, t3);
}

}  // namespace softraster::simd
#endif
