// sRGB's transfer function (IEC 61966-2-1) as GL applies it to SRGB8_ALPHA8 textures and
// framebuffers (docs/scene-format.md "Color spaces"). Alpha is never converted.
//   decode(c) = c / 12.92                    for c <= 0.04045
//             = ((c + 0.055) / 1.055)^2.4    above
//   encode(l) = 12.92 l                      for l <= 0.0031308
//             = 1.055 l^(1/2.4) - 0.055      above
// An 8-bit value k decodes to decode(k / 255) (a table of 256 floats). A linear value l is
// stored as floor(255 encode(clamp(l, 0, 1)) + 0.5), computed exactly: encode rises, so the
// stored value is the number of thresholds t_k = decode((k - 0.5) / 255), k = 1..255, that l
// reaches, and l >= t_k holds exactly when l reaches the least float at or above t_k.
#pragma once
#include <array>
#include <bit>
#include <cstdint>

#include "softraster/pipeline/simd.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <immintrin.h>
#endif

namespace softraster {
// How stored 8-bit color values relate to light (a texture's or a framebuffer's format):
// linear (GL_RGBA8) or sRGB-encoded (GL_SRGB8_ALPHA8).
enum class ColorSpace { Linear, Srgb };
}  // namespace softraster

namespace softraster::srgb {

struct Tables {
    std::array<float, 256> decode;     // decode(k / 255), in double then rounded
    // decode(k / 255) on the texture filter's fixed-point scale (texture.h "Precision"):
    // round(65280 decode(k / 255)), 0 to 65280.
    std::array<uint16_t, 256> decode_fixed;
    std::array<float, 257> threshold;  // [k]: the least float >= t_k; [0] = -inf, [256] = +inf
    // The stored value at the start of each of 13 x 128 intervals of [2^-13, 1): float bit
    // patterns >> 16 (exponent and 7 bits of mantissa) from that of 2^-13. No interval
    // holds two thresholds (a unit test checks), so one comparison finishes the job.
    static constexpr int kFirstBucket = 114 << 7;  // (bits of 2^-13) >> 16
    static constexpr int kBuckets = 13 << 7;
    std::array<int32_t, kBuckets> bucket_start;
};
const Tables& tables();

inline float decode(uint8_t k) { return tables().decode[k]; }
// decode(c) for any c in [0, 1], computed in double precision.
float decode_value(double c);

// The stored 8-bit value of linear l (NaN gives 0), with t = tables() (a caller encoding
// many values reads it once).
inline uint8_t encode(const Tables& t, float l) {
    if (!(l > 0.0f)) return 0;
    if (l >= 1.0f) return 255;
    int b = int(std::bit_cast<uint32_t>(l) >> 16) - Tables::kFirstBucket;
    b = b < 0 ? 0 : b;  // (l < 1: b < kBuckets)
    const int k = t.bucket_start[size_t(b)];
    return uint8_t(l >= t.threshold[size_t(k) + 1] ? k + 1 : k);
}
inline uint8_t encode(float l) { return encode(tables(), l); }

// Eight lanes, each as encode() computes it, into `out`. (Vectors by reference: see
// tone_mapping.h.)
inline void encode(const simd::f8& linear, simd::i8& out) {
    using simd::i8;
    const Tables& t = tables();
    const simd::f8 l = simd::clamp01(linear);  // NaN -> 0; 1 lands in the last interval
    i8 b = (std::bit_cast<i8>(l) >> 16) - Tables::kFirstBucket;
    b = simd::select(b < 0, simd::splat_i(0), simd::select(b >= Tables::kBuckets, simd::splat_i(Tables::kBuckets - 1), b));
    for (int lane = 0; lane < simd::kLanes; ++lane) {
        const int k = t.bucket_start[size_t(b[lane])];
        out[lane] = l[lane] >= t.threshold[size_t(k) + 1] ? k + 1 : k;
    }
}
#if SOFTRASTER_HAS_AVX2_PATH
// The same with two gathers for the lanes' table lookups (t: tables(), read once by the
// caller for its channels). max(l, 0) takes the second operand, 0, for a NaN, as clamp01.
[[gnu::target("avx2")]] inline void encode_avx2(const Tables& t, const simd::f8& linear, simd::i8& out) {
    const __m256 l = _mm256_min_ps(_mm256_max_ps(__m256(linear), _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
    __m256i b = _mm256_sub_epi32(_mm256_srli_epi32(_mm256_castps_si256(l), 16), _mm256_set1_epi32(Tables::kFirstBucket));
    b = _mm256_min_epi32(_mm256_max_epi32(b, _mm256_setzero_si256()), _mm256_set1_epi32(Tables::kBuckets - 1));
    const __m256i k = _mm256_i32gather_epi32(t.bucket_start.data(), b, 4);
    const __m256 next = _mm256_i32gather_ps(t.threshold.data() + 1, k, 4);
    out = simd::i8(_mm256_sub_epi32(k, _mm256_castps_si256(_mm256_cmp_ps(l, next, _CMP_GE_OQ))));  // (a true comparison is -1)
}
#endif

}  // namespace softraster::srgb
