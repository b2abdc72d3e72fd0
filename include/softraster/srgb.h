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
    // Its inverse: [decode_fixed[k]] = k, the other entries 0 (the values differ: a unit test
    // checks). An sRGB texture keeps only its decoded texels, and finds its stored bytes here.
    std::array<uint8_t, 65281> code_of_fixed;
    std::array<float, 257> threshold;  // [k]: the least float >= t_k; [0] = -inf, [256] = +inf
    // The encode's one lookup, for each of 13 x 128 intervals of [2^-13, 1): float bit
    // patterns >> 16 (exponent and 7 bits of mantissa) from that of 2^-13. No interval holds
    // two thresholds (a unit test checks), so an entry says all: the stored value k at the
    // interval's start (bits 17 and up), and the low 16 bits of the threshold the interval
    // holds, or 2^16 if it holds none (bits 0-16). A value in the interval stores k, plus 1
    // if its low 16 bits reach the threshold's: positive floats order as their bit patterns.
    // (One table read, where a value and then the next threshold took two dependent ones.)
    static constexpr int kFirstBucket = 114 << 7;  // (bits of 2^-13) >> 16
    static constexpr int kBuckets = 13 << 7;
    static constexpr int kNoThreshold = 1 << 16;
    std::array<int32_t, kBuckets> bucket;
    // The interval of a value in [0, 1]: below 2^-13, the first one, which holds no
    // threshold (a unit test checks); 1 in the last, which holds none either.
    static int bucket_of(uint32_t bits) {
        const int b = int(bits >> 16) - kFirstBucket;
        return b < 0 ? 0 : b >= kBuckets ? kBuckets - 1 : b;
    }
    static int stored(int32_t entry, uint32_t bits) { return (entry >> 17) + (int(bits & 0xffffu) >= (entry & 0x1ffff) ? 1 : 0); }
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
    const uint32_t bits = std::bit_cast<uint32_t>(l);
    return uint8_t(Tables::stored(t.bucket[size_t(Tables::bucket_of(bits))], bits));
}
inline uint8_t encode(float l) { return encode(tables(), l); }

// Eight lanes, each as encode() computes it, into `out` (t: tables(), read once by the
// caller for its groups). (Vectors by reference: see tone_mapping.h.)
inline void encode(const Tables& t, const simd::f8& linear, simd::i8& out) {
    const simd::f8 l = simd::clamp01(linear);  // NaN -> 0; 1 lands in the last interval
    for (int lane = 0; lane < simd::kLanes; ++lane) {
        const uint32_t bits = std::bit_cast<uint32_t>(l[lane]);
        out[lane] = Tables::stored(t.bucket[size_t(Tables::bucket_of(bits))], bits);
    }
}
#if SOFTRASTER_HAS_AVX2_PATH
// The same with one gather for the lanes' table entries (t: tables(), read once by the
// caller for its channels). max(l, 0) takes the second operand, 0, for a NaN, as clamp01.
[[gnu::target("avx2")]] inline void encode_avx2(const Tables& t, const simd::f8& linear, simd::i8& out) {
    const __m256i bits = _mm256_castps_si256(_mm256_min_ps(_mm256_max_ps(__m256(linear), _mm256_setzero_ps()), _mm256_set1_ps(1.0f)));
    __m256i b = _mm256_sub_epi32(_mm256_srli_epi32(bits, 16), _mm256_set1_epi32(Tables::kFirstBucket));
    b = _mm256_min_epi32(_mm256_max_epi32(b, _mm256_setzero_si256()), _mm256_set1_epi32(Tables::kBuckets - 1));
    const __m256i entry = _mm256_i32gather_epi32(t.bucket.data(), b, 4);
    const __m256i k = _mm256_srai_epi32(entry, 17), threshold = _mm256_and_si256(entry, _mm256_set1_epi32(0x1ffff));
    const __m256i low = _mm256_and_si256(bits, _mm256_set1_epi32(0xffff));
    // k + 1, less 1 where the threshold is past the value (a true comparison is -1).
    out = simd::i8(_mm256_add_epi32(_mm256_add_epi32(k, _mm256_set1_epi32(1)), _mm256_cmpgt_epi32(threshold, low)));
}
#endif

}  // namespace softraster::srgb
