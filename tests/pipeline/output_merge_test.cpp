// Output merge: every depth compare function, depth writes on and off, and the blend modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "softraster/pipeline/resolve.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 8, H = 8;

// Draws a full-screen quad at depth z over a buffer cleared to depth `stored`; returns
// whether the center pixel was written and the depth left there.
std::pair<bool, float> draw_at(DepthFunc f, float z, float stored, bool write = true) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1), stored);
    ctx.state.depth_func = f;
    ctx.state.depth_write = write;
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H, z), 0}, {window_to_clip(W, 0, W, H, z), 0},
                                   {window_to_clip(W, H, W, H, z), 0}, {window_to_clip(0, H, W, H, z), 0}};
    ctx.state.cull = CullMode::None;
    draw(ctx, ConstantColorShader{glm::vec4(1, 0, 0, 1)}, v, {0, 1, 2, 0, 2, 3});
    const size_t i = fb.sample_index(4, 4);
    return {fb.color_data()[i].r == 255, fb.depth_data()[i]};
}

}  // namespace

// A depth-only clear (depth passes) sets every sample's depth and leaves color and stencil.
TEST(Clear, DepthOnlyLeavesColorAndStencil) {
    Framebuffer fb(W, H, 4);
    fb.add_stencil();
    Context ctx(fb);
    ctx.clear(glm::vec4(0.2f, 0.4f, 0.6f, 1.0f), 0.25f, 7);
    ctx.finish();
    const Rgba8 color = fb.color_data()[0];
    ctx.clear_depth(0.75f);
    ctx.finish();
    for (size_t i = 0; i < size_t(W * H * 4); ++i) {
        ASSERT_EQ(fb.depth_data()[i], 0.75f) << i;
        ASSERT_EQ(fb.color_data()[i], color) << i;
        ASSERT_EQ(fb.stencil_data()[i], 7) << i;
    }
}

// Each plane starts on a cache line, so that two threads' tiles never share one
// (CacheLineAllocator): large buffers too, which the C library maps 16 bytes past a page.
TEST(Framebuffer, PlanesStartOnACacheLine) {
    for (auto [w, h, samples] : {std::array{W, H, 1}, std::array{1920, 1080, 1}, std::array{333, 77, 4}}) {
        Framebuffer fb(w, h, samples);
        fb.add_stencil();
        EXPECT_EQ(reinterpret_cast<uintptr_t>(fb.color_data()) % 64, 0u) << w;
        EXPECT_EQ(reinterpret_cast<uintptr_t>(fb.depth_data()) % 64, 0u) << w;
        EXPECT_EQ(reinterpret_cast<uintptr_t>(fb.stencil_data()) % 64, 0u) << w;
    }
}

TEST(DepthTest, EveryCompareFunction) {
    struct Case {
        DepthFunc f;
        bool less, equal, greater;  // passes when z < stored, z == stored, z > stored
    };
    const Case cases[] = {
        {DepthFunc::Never, false, false, false},     {DepthFunc::Less, true, false, false},
        {DepthFunc::Equal, false, true, false},      {DepthFunc::LessEqual, true, true, false},
        {DepthFunc::Greater, false, false, true},    {DepthFunc::NotEqual, true, false, true},
        {DepthFunc::GreaterEqual, false, true, true}, {DepthFunc::Always, true, true, true},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(draw_at(c.f, 0.25f, 0.5f).first, c.less) << int(c.f);
        EXPECT_EQ(draw_at(c.f, 0.5f, 0.5f).first, c.equal) << int(c.f);
        EXPECT_EQ(draw_at(c.f, 0.75f, 0.5f).first, c.greater) << int(c.f);
    }
}

TEST(DepthTest, WritesOnlyWhenEnabledAndPassing) {
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.25f, 0.5f, true).second, 0.25f);
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.25f, 0.5f, false).second, 0.5f);
    EXPECT_FLOAT_EQ(draw_at(DepthFunc::Less, 0.75f, 0.5f, true).second, 0.5f);
}

TEST(Blend, AlphaAndAdditiveFollowTheFormulasWithinOneLevel) {
    // The spec allows 8-bit fixed-point blending (source quantized first, as llvmpipe does):
    // the two roundings of the products plus the source's own quantization stay within 1.5
    // levels of the exact formula.
    auto near = [](uint8_t got, float formula) { return std::fabs(float(got) - 255.0f * formula) <= 1.5f; };
    for (int trial = 0; trial < 2000; ++trial) {
        const Rgba8 dst{uint8_t(trial * 37 % 256), uint8_t(trial * 91 % 256), uint8_t(trial * 13 % 256), uint8_t(trial * 53 % 256)};
        const glm::vec4 src(float(trial % 17) / 16, float(trial % 23) / 22, float(trial % 7) / 6, float(trial % 29) / 28);
        const glm::vec4 d = glm::vec4(dst.r, dst.g, dst.b, dst.a) / 255.0f;
        const Rgba8 a = blend(BlendMode::Alpha, src, dst);
        ASSERT_TRUE(near(a.r, src.r * src.a + d.r * (1 - src.a))) << trial;
        ASSERT_TRUE(near(a.g, src.g * src.a + d.g * (1 - src.a))) << trial;
        ASSERT_TRUE(near(a.a, src.a + d.a * (1 - src.a))) << trial;
        const Rgba8 add = blend(BlendMode::Additive, src, dst);
        ASSERT_TRUE(near(add.b, std::min(1.0f, src.b * src.a + d.b))) << trial;
        ASSERT_EQ(add.a, dst.a);  // additive keeps the destination alpha
    }
    EXPECT_EQ(blend(BlendMode::Additive, glm::vec4(1, 1, 1, 1), Rgba8{250, 250, 250, 255}).r, 255);  // saturates
    EXPECT_EQ(blend(BlendMode::Opaque, glm::vec4(2, -1, 0.5f, 1), Rgba8{}), (Rgba8{255, 0, 128, 255}));
    EXPECT_EQ(blend(BlendMode::Alpha, glm::vec4(1, 0, 0, 1), Rgba8{0, 255, 0, 255}), (Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(blend(BlendMode::Alpha, glm::vec4(1, 0, 0, 0), Rgba8{0, 255, 0, 255}), (Rgba8{0, 255, 0, 255}));
}

TEST(Blend, UnormProductIsRoundedExactly) {
    for (unsigned x = 0; x < 256; ++x)
        for (unsigned y = 0; y < 256; ++y)
            ASSERT_EQ(mul_unorm8(x, y), unsigned(std::floor(double(x) * y / 255.0 + 0.5))) << x << " " << y;
}

TEST(Quantize, RoundsHalfUpAndClamps) {
    EXPECT_EQ(quantize_unorm8(0.5f), 128);  // floor(127.5 + 0.5)
    EXPECT_EQ(quantize_unorm8(-0.1f), 0);
    EXPECT_EQ(quantize_unorm8(1.7f), 255);
    EXPECT_EQ(quantize_unorm8(NAN), 0);
    EXPECT_EQ(quantize_unorm8(1.0f / 255.0f), 1);
}

// Eight lanes quantized and packed (quantize_pack_rgba8) give each lane's quantize_unorm8, in
// the generic copy and in the AVX2 one, whose clamps are folded into the conversion and the
// saturating packs: values in and far out of [0, 1], the rounding edges, signed zeros,
// infinities and NaN.
TEST(Quantize, PackedLanesEqualOneAtATimeOnBothPaths) {
    std::vector<float> values = {0.0f, -0.0f, 1.0f, 0.5f, -0.1f, 1.7f, NAN, -NAN, INFINITY, -INFINITY, 3.0e9f, -3.0e9f, 1.0e38f, -1.0e38f,
                                 1.0f / 255.0f, 0.5f / 255.0f, std::nextafter(0.5f / 255.0f, 0.0f), std::nextafter(1.0f, 2.0f),
                                 std::nextafter(1.0f, 0.0f), 1.0e-30f, -1.0e-30f};
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> c(-0.5f, 1.5f);
    while (values.size() % 8 != 0 || values.size() < 4000) values.push_back(c(rng));
    std::uniform_int_distribution<size_t> pick(0, values.size() - 1);
    for (int trial = 0; trial < 4000; ++trial) {
        std::array<simd::f8, 4> src;
        uint32_t expected[8];
        for (int l = 0; l < simd::kLanes; ++l) {
            for (auto& ch : src) ch[l] = trial < int(values.size()) / 8 ? values[size_t(8 * trial + l)] : values[pick(rng)];
            const Rgba8 p{quantize_unorm8(src[0][l]), quantize_unorm8(src[1][l]), quantize_unorm8(src[2][l]), quantize_unorm8(src[3][l])};
            std::memcpy(&expected[l], &p, 4);
        }
        simd::i8 generic;
        quantize_pack_rgba8<false>(src, generic);
        ASSERT_EQ(std::memcmp(&generic, expected, sizeof expected), 0) << "generic, trial " << trial;
#if SOFTRASTER_HAS_AVX2_PATH
        if (simd::wide_path_runs()) {
            simd::i8 wide;
            quantize_pack_rgba8<true>(src, wide);
            ASSERT_EQ(std::memcmp(&wide, expected, sizeof expected), 0) << "AVX2, trial " << trial;
        }
#endif
    }
}

// Eight pixels at a time (blend_group; blend_row for Custom) give the same bytes as one at
// a time (blend), for every mode, lanes written or not, colors in and out of [0, 1] and NaN.
TEST(Blend, EightLanesEqualOneAtATime) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> c(-0.2f, 1.2f);
    std::uniform_int_distribution<int> byte(0, 255);
    for (BlendMode mode : {BlendMode::Opaque, BlendMode::Alpha, BlendMode::Additive, BlendMode::Custom})
        for (int trial = 0; trial < 3000; ++trial) {
            RenderState st;
            st.blend = mode;
            if (mode == BlendMode::Custom) {  // random equations, factors, constant and color mask
                BlendEquationState& e = st.blend_equation;
                auto eq = [&] { return BlendEquation(byte(rng) % 5); };
                auto factor = [&] { return BlendFactor(byte(rng) % 15); };
                e = {eq(), eq(), factor(), factor(), factor(), factor(), glm::vec4(c(rng), c(rng), c(rng), c(rng))};
                st.color_mask = uint8_t(byte(rng) % 16);
            }
            std::array<Rgba8, 8> row;
            for (Rgba8& p : row) p = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng))};
            std::array<simd::f8, 4> src;
            simd::i8 write;
            for (int l = 0; l < simd::kLanes; ++l) {
                for (auto& ch : src) ch[l] = trial % 97 == 0 && l == 3 ? NAN : c(rng);
                write[l] = byte(rng) < 200 ? -1 : 0;
            }
            std::array<Rgba8, 8> expected = row;
            for (int l = 0; l < simd::kLanes; ++l)
                if (write[l]) {
                    const glm::vec4 color(src[0][l], src[1][l], src[2][l], src[3][l]);
                    expected[size_t(l)] = mode == BlendMode::Custom ? blend(BlendSettings(st), color, row[size_t(l)])
                                                                    : blend(mode, color, row[size_t(l)]);
                }
            if (mode == BlendMode::Opaque) {
                blend_group<false>(BlendSettings(st), row.data(), 0, 8, write, src);
            } else if (mode == BlendMode::Custom) {
                RowGroups groups;
                simd::i8 packed;
                quantize_pack_rgba8(src, packed);
                groups.add(0, write, packed);
                blend_row<false>(BlendSettings(st), row.data(), 8, groups);
            } else {
                blend_group<true>(BlendSettings(st), row.data(), 0, 8, write, src);
            }
            ASSERT_EQ(std::memcmp(row.data(), expected.data(), sizeof row), 0) << "mode " << int(mode) << " trial " << trial;
        }
}

// A whole row of groups (blend_row, compiled once in src/pipeline/output_merge.cpp): each
// group blended into its own pixels, the row's last group cut by the picture's right edge,
// pixels outside the groups untouched.
TEST(Blend, RowOfGroupsEqualsOnePixelAtATime) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> c(0.0f, 1.0f);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int trial = 0; trial < 500; ++trial) {
        RenderState st;
        st.blend = BlendMode::Custom;
        BlendEquationState& e = st.blend_equation;
        auto eq = [&] { return BlendEquation(byte(rng) % 5); };
        auto factor = [&] { return BlendFactor(byte(rng) % 15); };
        e = {eq(), eq(), factor(), factor(), factor(), factor(), glm::vec4(c(rng), c(rng), c(rng), c(rng))};
        const BlendSettings settings(st);
        const int width = 61;  // the last group has five pixels
        std::vector<Rgba8> row(static_cast<size_t>(width));
        for (Rgba8& p : row) p = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng))};
        std::vector<Rgba8> expected = row;
        RowGroups groups;
        for (int x = 0; x < width; x += 8) {
            if (byte(rng) < 64) continue;  // a group the triangle misses
            std::array<simd::f8, 4> src;
            simd::i8 write;
            for (int l = 0; l < simd::kLanes; ++l) {
                for (auto& ch : src) ch[l] = c(rng);
                write[l] = x + l < width && byte(rng) < 200 ? -1 : 0;
                if (write[l])
                    expected[size_t(x + l)] = blend(settings, glm::vec4(src[0][l], src[1][l], src[2][l], src[3][l]), row[size_t(x + l)]);
            }
            simd::i8 packed;
            quantize_pack_rgba8(src, packed);
            groups.add(x, write, packed);
        }
        // Both CPU paths' copies (the AVX2 one where this CPU runs it).
        std::vector<Rgba8> wide = row;
        blend_row<false>(settings, row.data(), width, groups);
        ASSERT_EQ(std::memcmp(row.data(), expected.data(), row.size() * sizeof(Rgba8)), 0) << "trial " << trial;
        if (simd::wide_path_runs()) {
            blend_row<true>(settings, wide.data(), width, groups);
            ASSERT_EQ(std::memcmp(wide.data(), expected.data(), wide.size() * sizeof(Rgba8)), 0) << "AVX2, trial " << trial;
        }
    }
}

// The general blend (every equation and factor) agrees with the presets it generalizes, and
// its equations and special factors compute what GL specifies.
TEST(Blend, GeneralEquationsMatchThePresets) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    std::uniform_int_distribution<int> b(0, 255);
    for (BlendMode mode : {BlendMode::Opaque, BlendMode::Alpha, BlendMode::Additive}) {
        RenderState st;
        st.blend = mode;
        const BlendSettings general(st);
        for (int i = 0; i < 2000; ++i) {
            const glm::vec4 src(u(rng), u(rng), u(rng), u(rng));
            const Rgba8 dst{uint8_t(b(rng)), uint8_t(b(rng)), uint8_t(b(rng)), uint8_t(b(rng))};
            ASSERT_EQ(blend(general, src, dst), blend(mode, src, dst)) << int(mode);
        }
    }
}

TEST(Blend, EquationsFactorsAndMask) {
    RenderState st;
    st.blend = BlendMode::Custom;
    auto run = [&](const glm::vec4& src, Rgba8 dst) { return blend(BlendSettings(st), src, dst); };
    BlendEquationState& e = st.blend_equation;
    e.src_rgb = e.dst_rgb = e.src_alpha = e.dst_alpha = BlendFactor::One;
    const glm::vec4 s(0.4f, 0.8f, 0.2f, 0.6f);  // 102, 204, 51, 153
    const Rgba8 d{200, 100, 51, 50};
    e.rgb = e.alpha = BlendEquation::Subtract;
    EXPECT_EQ(run(s, d), (Rgba8{0, 104, 0, 103}));
    e.rgb = e.alpha = BlendEquation::ReverseSubtract;
    EXPECT_EQ(run(s, d), (Rgba8{98, 0, 0, 0}));
    e.rgb = e.alpha = BlendEquation::Min;
    EXPECT_EQ(run(s, d), (Rgba8{102, 100, 51, 50}));
    e.rgb = e.alpha = BlendEquation::Max;
    EXPECT_EQ(run(s, d), (Rgba8{200, 204, 51, 153}));
    e.rgb = e.alpha = BlendEquation::Add;
    e.src_rgb = BlendFactor::SrcAlphaSaturate;  // min(153, 255 - 50) = 153 for rgb, 1 for alpha
    e.dst_rgb = e.dst_alpha = BlendFactor::Zero;
    EXPECT_EQ(run(s, d), (Rgba8{uint8_t(mul_unorm8(102, 153)), uint8_t(mul_unorm8(204, 153)), uint8_t(mul_unorm8(51, 153)), 153}));
    e.src_rgb = BlendFactor::ConstantColor;
    e.constant = glm::vec4(0.5f, 0.0f, 1.0f, 0.0f);  // 128, 0, 255
    EXPECT_EQ(run(s, d), (Rgba8{uint8_t(mul_unorm8(102, 128)), 0, 51, 153}));
    st.color_mask = 0b1010;  // green and alpha only
    EXPECT_EQ(run(s, d), (Rgba8{200, 0, 51, 153}));
}

// An sRGB framebuffer: opaque colors stored encoded, blending in linear light (the float
// formula on decoded values, then encoded), masked channels kept; a clear encodes too.
TEST(Blend, SrgbBlendsInLinearLight) {
    RenderState st;
    st.blend = BlendMode::Alpha;
    const BlendSettings alpha(st, ColorSpace::Srgb);
    // Half white over black: half the light, which encodes to 188 (8-bit blending gives 128).
    EXPECT_EQ(blend(alpha, glm::vec4(1, 1, 1, 0.5f), Rgba8{0, 0, 0, 255}), (Rgba8{188, 188, 188, 255}));
    EXPECT_EQ(blend(BlendSettings(st), glm::vec4(1, 1, 1, 0.5f), Rgba8{0, 0, 0, 255}).r, 128);
    auto encoded = [](double l) {
        l = std::clamp(l, 0.0, 1.0);
        return int(std::floor(255 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055) + 0.5));
    };
    auto decoded = [](int k) {
        const double c = k / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    st.blend = BlendMode::Custom;
    st.blend_equation = {BlendEquation::Add, BlendEquation::Add, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha,
                         BlendFactor::One, BlendFactor::OneMinusSrcAlpha, glm::vec4(0.0f)};
    for (int trial = 0; trial < 3000; ++trial) {
        const glm::vec4 s(u(rng), u(rng), u(rng), std::clamp(u(rng), 0.0f, 1.0f));
        const Rgba8 d{uint8_t(rng() % 256), uint8_t(rng() % 256), uint8_t(rng() % 256), uint8_t(rng() % 256)};
        const Rgba8 got = blend(BlendSettings(st, ColorSpace::Srgb), s, d);
        const double a = s.a;
        auto want = [&](float sc, uint8_t dc) { return encoded(std::clamp(double(sc), 0.0, 1.0) * a + decoded(dc) * (1 - a)); };
        // (float arithmetic against double: a rounding boundary may fall between them)
        ASSERT_NEAR(got.r, want(s.r, d.r), 1) << trial;
        ASSERT_NEAR(got.b, want(s.b, d.b), 1) << trial;
        ASSERT_NEAR(got.a, std::floor(255 * (a + d.a / 255.0 * (1 - a)) + 0.5), 1) << trial;
    }
    st.color_mask = 0b0101;  // red and blue
    const Rgba8 masked = blend(BlendSettings(st, ColorSpace::Srgb), glm::vec4(1, 1, 1, 0.5f), Rgba8{0, 7, 0, 9});
    EXPECT_EQ(masked, (Rgba8{188, 7, 188, 9}));
    // Opaque: the color encoded once.
    st = RenderState{};
    Rgba8 samples[4] = {};
    merge_fragment<4, false>(BlendSettings(st, ColorSpace::Srgb), samples, 0b0110, glm::vec4(0.5f, 0.0f, 1.0f, 0.5f));
    EXPECT_EQ(samples[1], (Rgba8{188, 0, 255, 128}));
    EXPECT_EQ(samples[0], (Rgba8{}));
    Framebuffer fb(2, 2, 1, ColorSpace::Srgb);
    fb.clear_color(glm::vec4(0.5f, 0.5f, 0.5f, 0.5f));
    EXPECT_EQ(fb.color_data()[3], (Rgba8{188, 188, 188, 128}));
}

// Every back end stores an sRGB framebuffer's colors the same way: the fast one at 1 and 4
// samples, the general one (a stencil test; 8 samples) and blending (general, linear light).
TEST(Blend, SrgbFramebufferThroughEveryBackEnd) {
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H, 0.5f), 0}, {window_to_clip(W, 0, W, H, 0.5f), 0},
                                   {window_to_clip(W, H, W, H, 0.5f), 0}, {window_to_clip(0, H, W, H, 0.5f), 0}};
    for (int samples : {1, 4, 8})
        for (bool stencil : {false, true}) {
            Framebuffer fb(W, H, samples, ColorSpace::Srgb);
            Context ctx(fb);
            ctx.clear(glm::vec4(0, 0, 0, 1));
            ctx.state.cull = CullMode::None;
            ctx.state.stencil_test = stencil;
            draw(ctx, ConstantColorShader{glm::vec4(0.5f, 0.2f, 1.0f, 1.0f)}, v, {0, 1, 2, 0, 2, 3});
            ctx.state.blend = BlendMode::Alpha;
            ctx.state.depth_test = false;
            draw(ctx, ConstantColorShader{glm::vec4(0.0f, 0.0f, 0.0f, 0.5f)}, v, {0, 1, 2});  // darkens the lower right half
            const Image img = ctx.read_pixels();
            // One corner off the diagonal is covered by both draws, the other by the first only:
            // 0.5 of (0.5, 0.2, 1) is 0.25, 0.1, 0.5 of the light.
            const Rgba8 light{188, 124, 255, 255}, dark{137, 89, 188, 255};
            const Rgba8 a = img.at(W - 1, 0), b = img.at(0, H - 1);
            EXPECT_TRUE((a == light && b == dark) || (a == dark && b == light))
                << samples << " " << stencil << ": " << int(a.r) << " " << int(b.r);
        }
}
