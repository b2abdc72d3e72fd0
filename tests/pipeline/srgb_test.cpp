// sRGB's transfer function (srgb.h) against the formulas evaluated independently in double
// precision: every 8-bit value decodes to the formula's value, every float encodes to the
// rounded formula, the eight-lane form agrees, and the tables' shortcut holds everywhere.
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "softraster/framebuffer.h"
#include "softraster/srgb.h"
#include "softraster/srgb_avx512.h"

using namespace softraster;

namespace {

double decode_ref(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double encode_ref(double l) { return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }
int stored_ref(float l) {
    const double c = std::clamp(double(l), 0.0, 1.0);
    return int(std::floor(255.0 * encode_ref(c) + 0.5));
}

TEST(Srgb, DecodesEveryByteToTheFormula) {
    for (int k = 0; k < 256; ++k) EXPECT_EQ(srgb::decode(uint8_t(k)), float(decode_ref(k / 255.0))) << k;
    EXPECT_EQ(srgb::decode(0), 0.0f);
    EXPECT_EQ(srgb::decode(255), 1.0f);
}

TEST(Srgb, EncodingADecodedByteGivesItBack) {
    for (int k = 0; k < 256; ++k) EXPECT_EQ(int(srgb::encode(srgb::decode(uint8_t(k)))), k) << k;
}

// The texture filter's fixed-point decode (texture.h "Precision") has a value per byte, all
// different, so its inverse (how an sRGB texture, which keeps only its decoded texels, finds
// its stored bytes) gives every byte back.
TEST(Srgb, EveryFixedPointDecodeLeadsBackToItsByte) {
    const srgb::Tables& t = srgb::tables();
    for (int k = 0; k < 256; ++k) {
        EXPECT_EQ(t.decode_fixed[size_t(k)], uint16_t(std::lround(65280.0 * decode_ref(k / 255.0)))) << k;
        if (k > 0) {
            EXPECT_LT(t.decode_fixed[size_t(k - 1)], t.decode_fixed[size_t(k)]) << k;
        }
        EXPECT_EQ(int(t.code_of_fixed[t.decode_fixed[size_t(k)]]), k) << k;
    }
}

// Around each threshold (where the rounding changes) and at random: the formula's rounding.
// (Away from a threshold by more than the double formula's error, the two must agree.)
TEST(Srgb, EncodesFloatsAsTheRoundedFormula) {
    const srgb::Tables& t = srgb::tables();
    for (int k = 1; k < 256; ++k) {
        const float at = t.threshold[size_t(k)], below = std::nextafter(at, 0.0f);
        EXPECT_EQ(int(srgb::encode(at)), k) << k;
        EXPECT_EQ(int(srgb::encode(below)), k - 1) << k;
        EXPECT_GE(255.0 * encode_ref(at) + 0.5, k - 1e-9) << k;
        EXPECT_LT(255.0 * encode_ref(below) + 0.5, k + 1e-9) << k;
    }
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    std::uniform_real_distribution<float> e(-30.0f, 1.0f);
    for (int i = 0; i < 200000; ++i) {
        const float l = i % 2 ? u(rng) : std::exp2(e(rng));
        EXPECT_EQ(int(srgb::encode(l)), stored_ref(l)) << l;
    }
    EXPECT_EQ(srgb::encode(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(srgb::encode(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(srgb::encode(-std::numeric_limits<float>::infinity()), 0);
}

// The shortcut: each of the intervals the first lookup uses holds at most one threshold, so
// one comparison after it is enough.
TEST(Srgb, NoIntervalHoldsTwoThresholds) {
    const srgb::Tables& t = srgb::tables();
    for (int b = 0; b < srgb::Tables::kBuckets; ++b) {
        const uint32_t first = uint32_t(srgb::Tables::kFirstBucket + b) << 16;
        const float lo = std::bit_cast<float>(first), hi = std::bit_cast<float>(first + 0xffffu);
        int inside = 0;
        for (int k = 1; k < 256; ++k) inside += t.threshold[size_t(k)] > lo && t.threshold[size_t(k)] <= hi;
        EXPECT_LE(inside, 1) << b;
    }
    // Below the first interval every value stores 0, and so does the first interval, whose
    // entry those values read; 1 reads the last, which holds no threshold either.
    const float first_end = std::bit_cast<float>((uint32_t(srgb::Tables::kFirstBucket + 1) << 16) - 1);
    EXPECT_GT(t.threshold[1], first_end);
    EXPECT_EQ(t.bucket[0], srgb::Tables::kNoThreshold);
    EXPECT_EQ(t.bucket[srgb::Tables::kBuckets - 1], (255 << 17) | srgb::Tables::kNoThreshold);
}

// Each interval's entry: at its first and last float, and at every threshold and the floats
// either side, the stored value is the number of thresholds the value reaches.
TEST(Srgb, EveryIntervalsEntryCountsTheThresholds) {
    const srgb::Tables& t = srgb::tables();
    auto reached = [&](float l) { return int(std::upper_bound(t.threshold.begin() + 1, t.threshold.begin() + 256, l) - (t.threshold.begin() + 1)); };
    std::vector<float> values;
    for (int b = 0; b < srgb::Tables::kBuckets; ++b) {
        const uint32_t first = uint32_t(srgb::Tables::kFirstBucket + b) << 16;
        values.push_back(std::bit_cast<float>(first)), values.push_back(std::bit_cast<float>(first + 0xffffu));
    }
    for (int k = 1; k < 256; ++k)
        for (float l = std::nextafter(std::nextafter(t.threshold[size_t(k)], 0.0f), 0.0f), n = 0; n < 5; l = std::nextafter(l, 2.0f), ++n) values.push_back(l);
    for (float l : values) {
        if (l >= 1.0f) continue;
        ASSERT_EQ(int(srgb::encode(l)), reached(l)) << l;
    }
}

// Eight lanes at once (the generic vector code, and AVX2's with gathers where the CPU has
// it) give each lane's encode(): random values, every threshold and the float just below
// it, and the edges (NaN, infinities, signed zeros, denormals, 1 and past it).
TEST(Srgb, EightLanesAgreeWithOne) {
    std::vector<float> values = {std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f, -0.0f, 1e30f, -1e30f,
                                 std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::denorm_min(), 1e-30f, std::nextafter(1.0f, 0.0f), std::nextafter(1.0f, 2.0f)};
    const srgb::Tables& t = srgb::tables();
    for (int k = 1; k < 256; ++k) values.push_back(t.threshold[size_t(k)]), values.push_back(std::nextafter(t.threshold[size_t(k)], 0.0f));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-0.2f, 1.2f);
    while (values.size() < 8 * 20000) values.push_back(u(rng));
    for (size_t i = 0; i < values.size(); i += simd::kLanes) {
        simd::f8 l;
        for (int k = 0; k < simd::kLanes; ++k) l[k] = values[i + size_t(k)];
        simd::i8 got;
        srgb::encode(t, l, got);
        for (int k = 0; k < simd::kLanes; ++k) ASSERT_EQ(got[k], int(srgb::encode(l[k]))) << l[k];
#if SOFTRASTER_HAS_AVX2_PATH
        if (simd::wide_path_runs()) {
            simd::i8 wide;
            srgb::encode_avx2(t, l, wide);
            for (int k = 0; k < simd::kLanes; ++k) ASSERT_EQ(wide[k], int(srgb::encode(l[k]))) << "AVX2 " << l[k];
        }
#endif
    }
}

#if SOFTRASTER_HAS_AVX2_PATH
// The AVX-512 packing (srgb_avx512.h) against the table's encode, value by value: every float
// in [0, 1] goes through its approximation (under the sanitizers every 97th, and the 64
// floats at and below each threshold), with alpha quantized as quantize_unorm8 does; then the
// edges, and a batch of an odd number of groups, whose last group is packed alone.
TEST(Srgb, SixteenLanesEncodeEveryFloatExactly) {
    if (!simd::cpu_has_avx512()) GTEST_SKIP() << "this CPU has no AVX-512";
    constexpr int kGroups = 16;
    std::array<simd::f8, 4> rgba[kGroups];
    simd::i8 out[kGroups + 1];
    int filled = 0;
    auto check = [&](int groups) {
        out[groups] = simd::splat_i(-1);
        srgb::pack_groups_avx512(rgba, groups, out);
        for (int g = 0; g < groups; ++g)
            for (int lane = 0; lane < simd::kLanes; ++lane) {
                const uint32_t pixel = uint32_t(out[g][lane]);
                for (size_t c = 0; c < 3; ++c)
                    if (int(pixel >> (8 * c) & 255u) != srgb::encode(rgba[g][c][lane]))
                        FAIL() << rgba[g][c][lane] << " in channel " << c << " stored as " << (pixel >> (8 * c) & 255u);
                const float a = rgba[g][3][lane];
                if (pixel >> 24 != quantize_unorm8(a)) FAIL() << "alpha " << a << " stored as " << (pixel >> 24);
            }
        ASSERT_EQ(out[groups][0], -1) << "a group past the batch written";
        filled = 0;
    };
    // Values into r, g and b, alpha the same value as r (every value is an alpha somewhere).
    auto add = [&](float l) {
        const int g = filled / 24, channel = filled / 8 % 3, lane = filled % 8;
        rgba[g][size_t(channel)][lane] = l;
        if (channel == 0) rgba[g][3][lane] = l;
        if (++filled == 24 * kGroups) check(kGroups);
    };
#ifdef SOFTRASTER_UNDER_SANITIZERS
    constexpr uint32_t kStep = 97;
#else
    constexpr uint32_t kStep = 1;
#endif
    for (uint32_t bits = 0; bits <= std::bit_cast<uint32_t>(1.0f); bits += kStep) add(std::bit_cast<float>(bits));
    const srgb::Tables& t = srgb::tables();
    for (int k = 1; k < 256; ++k)
        for (uint32_t below = 0; below < 64; ++below) add(std::bit_cast<float>(std::bit_cast<uint32_t>(t.threshold[size_t(k)]) - below));
    for (float edge : {std::numeric_limits<float>::quiet_NaN(), -0.0f, -1.0f, std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), std::nextafter(1.0f, 2.0f), 2.0f, 1e30f})
        add(edge);
    while (filled % 24 != 0) add(0.5f);
    check(filled / 24);
    for (int i = 0; i < 3 * 24; ++i) add(float(i) / 71.0f);  // three groups
    check(3);
}
#endif

TEST(Srgb, AColorKeepsItsAlphaLinear) {
    const Rgba8 c = quantize_rgba8({0.5f, 0.0f, 1.0f, 0.5f}, ColorSpace::Srgb);
    EXPECT_EQ(c, (Rgba8{188, 0, 255, 128}));
}

}  // namespace
