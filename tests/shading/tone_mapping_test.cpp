// Exposure and the tone curves (tone_mapping.h) against values worked out by hand and by
// their properties: Reinhard and ACES rise, stay in [0, 1) and [0, 1], and leave alpha alone.
#include <gtest/gtest.h>

#include "softraster/shading/tone_mapping.h"

using namespace softraster;

namespace {

TEST(ToneMapping, NoneOnlyScalesByTheExposure) {
    const ToneMapping t{ToneCurve::None, 2.0f};
    EXPECT_TRUE(t.active());
    EXPECT_FALSE(ToneMapping{}.active());
    const glm::vec4 c = tone_map(t, {0.25f, 1.0f, 3.0f, 0.5f});
    EXPECT_EQ(c, glm::vec4(0.5f, 2.0f, 6.0f, 0.5f));
}

TEST(ToneMapping, ReinhardIsXOverOnePlusX) {
    const glm::vec4 c = tone_map({ToneCurve::Reinhard, 1.0f}, {0.0f, 1.0f, 3.0f, 0.25f});
    EXPECT_FLOAT_EQ(c.r, 0.0f);
    EXPECT_FLOAT_EQ(c.g, 0.5f);
    EXPECT_FLOAT_EQ(c.b, 0.75f);
    EXPECT_EQ(c.a, 0.25f);
    // Exposure first: 0.5 * 2 = 1 -> 0.5.
    EXPECT_FLOAT_EQ(tone_map({ToneCurve::Reinhard, 2.0f}, {0.5f, 0.5f, 0.5f, 1.0f}).r, 0.5f);
}

TEST(ToneMapping, AcesFitAtKnownPoints) {
    // x = 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 2.54 / 3.16.
    EXPECT_NEAR(tone_map({ToneCurve::Aces, 1.0f}, glm::vec4(1.0f)).r, 2.54 / 3.16, 1e-6);
    // x = 0.18 (middle gray): 0.18 (0.4518 + 0.03) / (0.18 (0.4374 + 0.59) + 0.14).
    EXPECT_NEAR(tone_map({ToneCurve::Aces, 1.0f}, glm::vec4(0.18f)).r, 0.18 * 0.4818 / (0.18 * 1.0274 + 0.14), 1e-6);
    EXPECT_EQ(tone_map({ToneCurve::Aces, 1.0f}, glm::vec4(0.0f)).r, 0.0f);
    EXPECT_EQ(tone_map({ToneCurve::Aces, 1.0f}, glm::vec4(1e6f)).r, 1.0f);  // clamped
}

TEST(ToneMapping, CurvesRiseAndStayInRange) {
    for (ToneCurve curve : {ToneCurve::Reinhard, ToneCurve::Aces}) {
        float last = -1.0f;
        for (float x = 0.0f; x < 100.0f; x = x * 1.1f + 0.001f) {
            const float y = tone_map({curve, 1.0f}, glm::vec4(x)).r;
            EXPECT_GE(y, last) << x;
            EXPECT_GE(y, 0.0f);
            EXPECT_LE(y, 1.0f);
            last = y;
        }
    }
}

TEST(ToneMapping, EightLanesAgreeWithOne) {
    for (ToneCurve curve : {ToneCurve::None, ToneCurve::Reinhard, ToneCurve::Aces}) {
        const ToneMapping t{curve, 1.7f};
        std::array<simd::f8, 4> c;
        for (int k = 0; k < simd::kLanes; ++k) c[0][k] = 0.3f * float(k), c[1][k] = 0.01f * float(k), c[2][k] = 5.0f * float(k), c[3][k] = 0.5f;
        std::array<simd::f8, 4> lanes = c;
        tone_map(t, lanes);
        for (int k = 0; k < simd::kLanes; ++k) {
            const glm::vec4 one = tone_map(t, {c[0][k], c[1][k], c[2][k], c[3][k]});
            for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(lanes[size_t(ch)][k], one[ch]) << k;
        }
    }
}

}  // namespace
