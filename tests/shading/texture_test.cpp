// Texture sampling: orientation, nearest and bilinear filtering, the four wrap modes, the
// mipmap chain, the level of detail, trilinear and anisotropic filtering.
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <utility>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>

#include "softraster/shading/texture.h"
#include "texture_test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {
// 2 x 2 picture, row 0 at the top: top-left red, top-right green, bottom-left blue, bottom-right white.
Texture four_texels() {
    Image img(2, 2);
    img.at(0, 0) = {255, 0, 0, 255};
    img.at(1, 0) = {0, 255, 0, 255};
    img.at(0, 1) = {0, 0, 255, 255};
    img.at(1, 1) = {255, 255, 255, 255};
    return Texture(img);
}
}  // namespace

TEST(Texture, OriginIsBottomLeftOfThePicture) {
    const Texture t = four_texels();
    EXPECT_EQ(t.sample(glm::vec2(0.25f, 0.25f), Filter::Nearest, Wrap::Clamp), glm::vec4(0, 0, 1, 1));  // blue
    EXPECT_EQ(t.sample(glm::vec2(0.25f, 0.75f), Filter::Nearest, Wrap::Clamp), glm::vec4(1, 0, 0, 1));  // red
    EXPECT_EQ(t.sample(glm::vec2(0.75f, 0.75f), Filter::Nearest, Wrap::Clamp), glm::vec4(0, 1, 0, 1));  // green
}

TEST(Texture, BilinearBlendsTheFourNearestCenters) {
    const Texture t = four_texels();
    const glm::vec4 mid = t.sample(glm::vec2(0.5f, 0.5f), Filter::Bilinear, Wrap::Clamp);
    EXPECT_NEAR(mid.r, 0.5f, 1e-6f);  // (1 + 0 + 0 + 1) / 4
    EXPECT_NEAR(mid.g, 0.5f, 1e-6f);
    EXPECT_NEAR(mid.b, 0.5f, 1e-6f);
    // At a texel center, exactly that texel.
    EXPECT_EQ(t.sample(glm::vec2(0.25f, 0.25f), Filter::Bilinear, Wrap::Clamp), glm::vec4(0, 0, 1, 1));
    // Between the bottom two centers, a quarter of the way.
    const glm::vec4 q = t.sample(glm::vec2(0.375f, 0.25f), Filter::Bilinear, Wrap::Clamp);
    EXPECT_NEAR(q.r, 0.25f, 1e-6f);
    EXPECT_NEAR(q.b, 1.0f, 1e-6f);
}

TEST(Texture, RepeatWrapsAndClampHoldsTheEdge) {
    const Texture t = four_texels();
    EXPECT_EQ(t.sample(glm::vec2(1.25f, -0.75f), Filter::Nearest, Wrap::Repeat), glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(t.sample(glm::vec2(-3.75f, 2.25f), Filter::Nearest, Wrap::Repeat), glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(t.sample(glm::vec2(5.0f, -5.0f), Filter::Nearest, Wrap::Clamp), glm::vec4(1, 1, 1, 1));
    // Bilinear at u = 0 (edge): repeat blends with the opposite column, clamp does not.
    const glm::vec4 rep = t.sample(glm::vec2(0.0f, 0.25f), Filter::Bilinear, Wrap::Repeat);
    const glm::vec4 clamp = t.sample(glm::vec2(0.0f, 0.25f), Filter::Bilinear, Wrap::Clamp);
    EXPECT_NEAR(rep.r, 0.5f, 1e-6f);
    EXPECT_NEAR(clamp.r, 0.0f, 1e-6f);
}

// A coordinate that is NaN, infinite or huge reads texels of the texture, never memory
// beside it: nearest gives one of the four texels exactly, bilinear a blend of them (every
// channel finite and within the texels' range). Each texel has its own alpha, so a read
// past the texels would show in it too.
TEST(Texture, NonFiniteCoordinatesAreSafe) {
    Image img(2, 2);
    img.at(0, 0) = {255, 0, 0, 64};
    img.at(1, 0) = {0, 255, 0, 128};
    img.at(0, 1) = {0, 0, 255, 192};
    img.at(1, 1) = {255, 255, 255, 255};
    const Texture t(img);
    auto texel = [&](int x, int y) {
        const Rgba8 c = img.at(x, y);
        return glm::vec4(c.r, c.g, c.b, c.a) / 255.0f;
    };
    const glm::vec4 texels[4] = {texel(0, 0), texel(1, 0), texel(0, 1), texel(1, 1)};
    int checked = 0;
    for (float bad : {NAN, INFINITY, -INFINITY, 3e38f})
        for (glm::vec2 uv : {glm::vec2(bad, 0.5f), glm::vec2(0.5f, bad), glm::vec2(bad, bad)})
            for (Filter f : {Filter::Nearest, Filter::Bilinear})
                for (Wrap w : {Wrap::Repeat, Wrap::Clamp}) {
                    SCOPED_TRACE(testing::Message() << "uv " << uv.x << "," << uv.y << " filter " << int(f) << " wrap " << int(w));
                    const glm::vec4 c = t.sample(uv, f, w);
                    for (int k = 0; k < 4; ++k) {
                        ASSERT_TRUE(std::isfinite(c[k]));
                        EXPECT_GE(c[k], 0.0f);
                        EXPECT_LE(c[k], 1.0f);
                    }
                    EXPECT_GE(c.a, 64.0f / 255.0f);
                    auto is = [&](const glm::vec4& expected) { return glm::all(glm::lessThan(glm::abs(c - expected), glm::vec4(1e-6f))); };
                    if (f == Filter::Nearest) {
                        EXPECT_TRUE(is(texels[0]) || is(texels[1]) || is(texels[2]) || is(texels[3])) << c.r << " " << c.g << " " << c.b << " " << c.a;
                    }
                    ++checked;
                }
    EXPECT_EQ(checked, 48);
}


// The chain halves to 1x1; each texel of a level is the rounded average of the 2x2 under it.
TEST(Texture, MipmapChainAveragesTwoByTwo) {
    const Texture t = pattern_texture(8, 4);
    ASSERT_EQ(t.levels(), 4);  // 8x4, 4x2, 2x1, 1x1
    EXPECT_EQ(t.level_width(1), 4);
    EXPECT_EQ(t.level_height(1), 2);
    EXPECT_EQ(t.level_width(3), 1);
    EXPECT_EQ(t.level_height(3), 1);
    for (int level = 1; level < t.levels(); ++level)
        for (int j = 0; j < t.level_height(level); ++j)
            for (int i = 0; i < t.level_width(level); ++i) {
                const int pw = t.level_width(level - 1), ph = t.level_height(level - 1);
                for (int c = 0; c < 4; ++c) {
                    int sum = 0;
                    for (int dj = 0; dj < 2; ++dj)
                        for (int di = 0; di < 2; ++di)
                            sum += int(std::lround(t.texel(level - 1, std::min(2 * i + di, pw - 1), std::min(2 * j + dj, ph - 1))[c] * 255.0f));
                    EXPECT_EQ(std::lround(t.texel(level, i, j)[c] * 255.0f), (sum + 2) / 4) << level << " " << i << "," << j << " " << c;
                }
            }
}

// An sRGB texture: texels read decoded, stored bytes kept; its mipmaps average the 2x2
// texels in linear light and store the encoded mean (black and white make 188, not 128).
TEST(Texture, SrgbTexelsAreDecodedAndTheirMipmapsAveragedInLinearLight) {
    Image img(2, 2);
    img.at(0, 0) = img.at(1, 1) = {255, 255, 255, 255};
    img.at(1, 0) = img.at(0, 1) = {0, 0, 0, 0};
    const Texture linear(img), srgb(img, ColorSpace::Srgb);
    EXPECT_TRUE(srgb.srgb());
    EXPECT_EQ(linear.stored(1, 0, 0), (Rgba8{128, 128, 128, 128}));
    EXPECT_EQ(srgb.stored(1, 0, 0), (Rgba8{188, 188, 188, 128}));  // alpha stays linear
    EXPECT_EQ(srgb.texel(1, 0, 0).r, srgb::decode(188));
    EXPECT_EQ(srgb.texel(1, 0, 0).a, 128.0f / 255.0f);
    // A bilinear lookup halfway between a white and a black texel: half the light.
    EXPECT_FLOAT_EQ(srgb.sample(glm::vec2(0.5f, 0.25f), Filter::Bilinear, Wrap::Clamp).r, 0.5f);
    EXPECT_FLOAT_EQ(linear.sample(glm::vec2(0.5f, 0.25f), Filter::Bilinear, Wrap::Clamp).r, 0.5f);
    // Each mip texel of a larger texture: the encoded mean of its four decoded texels.
    const Texture t = pattern_texture(8, 4, ColorSpace::Srgb);
    for (int j = 0; j < t.level_height(1); ++j)
        for (int i = 0; i < t.level_width(1); ++i)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int dj = 0; dj < 2; ++dj)
                    for (int di = 0; di < 2; ++di) sum += t.texel(0, 2 * i + di, 2 * j + dj)[c];
                const double l = sum / 4, e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
                const Rgba8 s = t.stored(1, i, j);
                EXPECT_NEAR((&s.r)[c], 255 * e, 0.5 + 1e-3) << i << "," << j << " " << c;
            }
}

// GL's level of detail: log2 of the texels a pixel step covers; nearest rounds it, linear
// takes the two levels around it. Powers of two are exact in llvmpipe's approximation too.
TEST(Texture, LevelOfDetailFollowsTheFootprint) {
    const Texture t = pattern_texture(64, 64);  // 7 levels
    Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
    s.mip = MipFilter::Nearest;
    EXPECT_FALSE(t.select_lod(isotropic(1.0f, 64), s).minified);  // one texel per pixel: magnification's edge
    EXPECT_FALSE(t.select_lod(isotropic(0.5f, 64), s).minified);
    EXPECT_EQ(t.select_lod(isotropic(4.0f, 64), s).level0, 2);
    EXPECT_EQ(t.select_lod(isotropic(5.6f, 64), s).level0, 2);  // log2 5.6 = 2.49
    EXPECT_EQ(t.select_lod(isotropic(5.7f, 64), s).level0, 3);  // 2.51
    EXPECT_EQ(t.select_lod(isotropic(1e6f, 64), s).level0, 6);  // clamped to the 1x1 level
    s.mip = MipFilter::Linear;
    LevelChoice c = t.select_lod(isotropic(8.0f, 64), s);
    EXPECT_TRUE(c.minified);
    EXPECT_EQ(c.level0, 3);
    EXPECT_EQ(c.weight, 0.0f);
    c = t.select_lod(isotropic(12.0f, 64), s);  // log2 144 ~ 7 + (144 / 128 - 1) = 7.125, halved
    EXPECT_EQ(c.level0, 3);
    EXPECT_EQ(c.level1, 4);
    EXPECT_FLOAT_EQ(c.weight, 0.5625f);
    // The larger of the two axes decides (GL's rho), and a zero footprint is magnification.
    EXPECT_EQ(t.select_lod(UvDerivatives{0.0f, 0.5f / 64, 4.0f / 64, 0.0f}, s).level0, 2);
    EXPECT_FALSE(t.select_lod(UvDerivatives{}, s).minified);
    for (float bad : {NAN, INFINITY})  // no crash, a level in the chain
        EXPECT_LE(t.select_lod(UvDerivatives{bad, bad, bad, bad}, s).level0, 6);
}

TEST(Texture, TrilinearBlendsTwoLevels) {
    const Texture t = pattern_texture(64, 64);
    Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
    s.mip = MipFilter::Linear;
    const glm::vec2 uv(0.3f, 0.6f);
    const UvDerivatives d = isotropic(12.0f, 64);  // levels 3 and 4, weight 0.5625
    Sampler one = s;
    one.mip = MipFilter::None;
    const LevelChoice c = t.select_lod(d, s);
    // Level k alone, through a texture whose level 0 is that level: the chain's own lookups.
    auto level_lookup = [&](int level) {
        Image img(t.level_width(level), t.level_height(level));
        for (int j = 0; j < img.height; ++j)
            for (int i = 0; i < img.width; ++i) {
                const glm::vec4 v = t.texel(level, i, img.height - 1 - j) * 255.0f;
                img.at(i, j) = {uint8_t(std::lround(v.r)), uint8_t(std::lround(v.g)), uint8_t(std::lround(v.b)), uint8_t(std::lround(v.a))};
            }
        return Texture(img).sample(uv, one);
    };
    const glm::vec4 a = level_lookup(c.level0), b = level_lookup(c.level1), got = t.sample(uv, d, s);
    // The fixed-point blends stay within 2/65280 of the float blend (texture.h "Precision").
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], a[k] + (b[k] - a[k]) * 0.5625f, 2.0f / 65280.0f);
}

// An 8-bit texture filters in fixed point: the sample point cut to 1/256 texel, the channel
// carried as value x 256. Hand values on one row of two texels, 0 and 255 (red) or 10 and 70.
TEST(Texture, FixedPointBilinearValues) {
    Image img(2, 1);
    img.at(0, 0) = {0, 10, 0, 255};
    img.at(1, 0) = {255, 70, 0, 255};
    const Texture t(img);
    const Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Clamp);
    // u = 0.25 + 0.3 / 2: x = 0.3 texels past texel 0's center, cut to 76/256 (0.296875).
    const glm::vec4 c = t.sample(glm::vec2(0.4f, 0.5f), s);
    EXPECT_EQ(c.r, float(255 * 76) * Texture::kFixedToUnit);            // 256 * 0 + (255 - 0) * 76
    EXPECT_EQ(c.g, float(10 * 256 + 60 * 76) * Texture::kFixedToUnit);  // 256 * 10 + (70 - 10) * 76
    EXPECT_EQ(c.a, 1.0f);
    // A texel center gives the texel's own 8-bit conversion, bit for bit.
    EXPECT_EQ(t.sample(glm::vec2(0.75f, 0.5f), s).g, 70.0f * (1.0f / 255.0f));
    // The level blend: an 8-bit weight, v0 - (v0 w >> 8) + (v1 w >> 8). Level 0's columns
    // are 201 and 100, so level 1's first texel is their average, 151 (rounded).
    Image big(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) big.at(x, y) = x % 2 ? Rgba8{100, 0, 0, 255} : Rgba8{201, 0, 0, 255};
    const Texture chain(big);
    Sampler tri = Sampler::plain(Filter::Nearest, Wrap::Clamp);
    tri.mip = MipFilter::Linear;
    const UvDerivatives d = isotropic(1.3f, 4);  // rho^2 = 1.69: lod 0.345, weight 88/256 once cut
    const LevelChoice lod = chain.select_lod(d, tri);
    ASSERT_EQ(lod.level0, 0);
    ASSERT_EQ(int(std::floor(lod.weight * 256.0f)), 88);
    const int v0 = 201 * 256, v1 = 151 * 256;
    EXPECT_EQ(chain.sample(glm::vec2(0.1f, 0.1f), d, tri).r, float(v0 - ((v0 * 88) >> 8) + ((v1 * 88) >> 8)) * Texture::kFixedToUnit);
}

// An sRGB texture filters in fixed point too, its texels' r, g, b decoded onto the scale
// first (srgb::Tables::decode_fixed), the sample point and weights in 1/4096 steps: within
// 3/65280 of the exact formula with the same cut weights (texture.h "Precision"), and a
// texel center gives its decoded value to 1/130560.
TEST(Texture, SrgbFixedPointIsWithinItsBound) {
    std::mt19937 rng(23);
    std::uniform_int_distribution<int> byte(0, 255);
    Image img(16, 8);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) img.at(x, y) = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng))};
    const Texture t(img, ColorSpace::Srgb);
    const Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Clamp);
    std::uniform_real_distribution<float> coord(0.0f, 1.0f);
    auto exact = [&](int i, int j, int c) {  // texel (i, j) clamped, decoded in double
        const Rgba8 v = t.stored(0, std::clamp(i, 0, t.width() - 1), std::clamp(j, 0, t.height() - 1));
        const int k = (&v.r)[c];
        if (c == 3) return k / 255.0;
        const double e = k / 255.0;
        return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
    };
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const glm::vec2 uv(coord(rng), coord(rng));
        // (the sample point and the weights in 1/4096 steps for sRGB)
        const int x = int(std::floor(uv.x * float(t.width()) * 4096.0f)) - 2048, y = int(std::floor(uv.y * float(t.height()) * 4096.0f)) - 2048;
        const int i = x >> 12, j = y >> 12;
        const double fx = (x & 4095) / 4096.0, fy = (y & 4095) / 4096.0;
        const glm::vec4 got = t.sample(uv, s);
        for (int c = 0; c < 4; ++c) {
            const double bottom = exact(i, j, c) * (1 - fx) + exact(i + 1, j, c) * fx, top = exact(i, j + 1, c) * (1 - fx) + exact(i + 1, j + 1, c) * fx;
            const double want = bottom * (1 - fy) + top * fy;
            worst = std::max(worst, std::abs(double(got[c]) - want));
            ASSERT_LE(std::abs(double(got[c]) - want), 3.0 / 65280.0) << "trial " << trial << " channel " << c;
        }
    }
    EXPECT_GT(worst, 0.0);  // (fixed point: not the float formula's bits)
    for (int j = 0; j < t.height(); ++j)
        for (int i = 0; i < t.width(); ++i) {
            const glm::vec4 got = t.sample(glm::vec2((float(i) + 0.5f) / float(t.width()), (float(j) + 0.5f) / float(t.height())), s);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], exact(i, j, c), 0.5 / 65280.0 + 1e-7) << i << "," << j << " " << c;
        }
}

TEST(Texture, MirrorAndBorderWrapping) {
    const Texture t = four_texels();  // bottom row: blue, white; top row: red, green
    const Sampler mirror = Sampler::plain(Filter::Nearest, Wrap::Mirror);
    EXPECT_EQ(t.sample(glm::vec2(1.25f, 0.25f), mirror), glm::vec4(1, 1, 1, 1));   // mirrored: white, then blue
    EXPECT_EQ(t.sample(glm::vec2(1.75f, 0.25f), mirror), glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(t.sample(glm::vec2(-0.25f, 0.25f), mirror), glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(t.sample(glm::vec2(2.25f, 0.25f), mirror), glm::vec4(0, 0, 1, 1));  // period 2
    Sampler border = Sampler::plain(Filter::Nearest, Wrap::Border);
    border.border = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    EXPECT_EQ(t.sample(glm::vec2(1.25f, 0.25f), border), border.border);
    EXPECT_EQ(t.sample(glm::vec2(0.25f, 0.25f), border), glm::vec4(0, 0, 1, 1));
    // Bilinear at the edge: half the edge texel, half the border.
    border.mag = border.min = Filter::Bilinear;
    const glm::vec4 edge = t.sample(glm::vec2(0.0f, 0.25f), border);
    EXPECT_NEAR(edge.r, 0.125f, 1e-6f);
    EXPECT_NEAR(edge.b, 0.875f, 1e-6f);
    // Different modes per axis.
    Sampler mixed = Sampler::plain(Filter::Nearest, Wrap::Repeat);
    mixed.wrap_t = Wrap::Clamp;
    EXPECT_EQ(t.sample(glm::vec2(1.25f, 3.0f), mixed), glm::vec4(1, 0, 0, 1));  // u wraps, v holds the top row
}

// Anisotropic filtering: N = ceil(P_max / P_min) lookups (at most the sampler's limit) along
// the footprint's long axis, each at the level of detail of P_max / N.
TEST(Texture, AnisotropicProbeCountAndLevel) {
    const Texture t = pattern_texture(256, 256);  // 9 levels
    Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
    s.mip = MipFilter::Linear;
    s.max_anisotropy = 16;
    auto footprint = [](float along_x, float along_y) {  // texels per pixel step, x along u, y along v
        return UvDerivatives{along_x / 256.0f, 0.0f, 0.0f, along_y / 256.0f};
    };
    LevelChoice c = t.select_lod(footprint(32.0f, 4.0f), s);  // 8 : 1
    EXPECT_EQ(c.probes, 8);
    EXPECT_EQ(c.level0, 2);  // log2(32 / 8)
    EXPECT_EQ(c.weight, 0.0f);
    EXPECT_EQ(c.axis_u, 32.0f / 256.0f);
    EXPECT_EQ(c.axis_v, 0.0f);
    c = t.select_lod(footprint(4.0f, 10.0f), s);  // 2.5 : 1, the long axis along y
    EXPECT_EQ(c.probes, 3);
    EXPECT_EQ(c.axis_u, 0.0f);
    EXPECT_EQ(c.axis_v, 10.0f / 256.0f);
    EXPECT_EQ(t.select_lod(footprint(64.0f, 0.0f), s).probes, 16);  // no width: the limit
    EXPECT_EQ(t.select_lod(footprint(64.0f, 2.0f), s).probes, 16);  // 32 : 1, capped
    EXPECT_EQ(t.select_lod(footprint(64.0f, 2.0f), s).level0, 2);   // log2(64 / 16)
    EXPECT_EQ(t.select_lod(footprint(8.0f, 8.0f), s).probes, 1);    // round: one lookup
    EXPECT_EQ(t.select_lod(footprint(0.5f, 0.01f), s).probes, 1);   // magnified: no probes
    s.max_anisotropy = 4;
    c = t.select_lod(footprint(32.0f, 4.0f), s);
    EXPECT_EQ(c.probes, 4);
    EXPECT_EQ(c.level0, 3);  // log2(32 / 4)
    s.max_anisotropy = 1;
    EXPECT_EQ(t.select_lod(footprint(32.0f, 4.0f), s).probes, 1);
    EXPECT_EQ(t.select_lod(footprint(32.0f, 4.0f), s).level0, 5);  // GL's rho: the long axis
    s.max_anisotropy = 16;
    for (float bad : {NAN, INFINITY})  // no crash, a count in range
        EXPECT_LE(t.select_lod(UvDerivatives{bad, bad, bad, bad}, s).probes, 16);
}

// What the probes buy, as properties: a round footprint (or a limit of 1) reads exactly what
// trilinear reads; a flat color stays flat; and where the texture does not change along the
// footprint's long axis, the result is the sharp lookup at P_max / N (trilinear blurs to P_max).
TEST(Texture, AnisotropicFilteringProperties) {
    Sampler tri = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
    tri.mip = MipFilter::Linear;
    Sampler aniso = tri;
    aniso.max_anisotropy = 16;
    const Texture t = pattern_texture(64, 64);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> coord(-2.0f, 2.0f), scale(0.5f, 40.0f);
    for (int trial = 0; trial < 200; ++trial) {  // round footprints (both axes the same length): the same bits
        const glm::vec2 uv(coord(rng), coord(rng));
        const float r = scale(rng) / 64.0f;
        const UvDerivatives round = trial % 2 ? UvDerivatives{r, 0.0f, 0.0f, r} : UvDerivatives{0.0f, -r, r, 0.0f};
        ASSERT_EQ(t.select_lod(round, aniso).probes, 1);
        EXPECT_EQ(t.sample(uv, round, aniso), t.sample(uv, round, tri));
        Sampler off = aniso;
        off.max_anisotropy = 1;
        const UvDerivatives stretched{r * 5.0f, 0.0f, 0.0f, r};
        EXPECT_EQ(t.sample(uv, stretched, off), t.sample(uv, stretched, tri));
    }
    Image gray(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) gray.at(x, y) = {77, 77, 77, 255};
    const Texture flat(gray);
    for (int trial = 0; trial < 100; ++trial) {
        const UvDerivatives d{scale(rng) / 16.0f, 0.1f / 16.0f, 0.0f, scale(rng) / 160.0f};
        const glm::vec4 c = flat.sample(glm::vec2(coord(rng), coord(rng)), d, aniso);
        EXPECT_NEAR(c.r, 77.0f / 255.0f, 1e-6f);
        EXPECT_NEAR(c.a, 1.0f, 1e-6f);
    }
    // Stripes across v, constant along u; the footprint 32 texels along u, 4 along v.
    Image stripes(256, 256);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) stripes.at(x, y) = y % 16 < 8 ? Rgba8{255, 255, 255, 255} : Rgba8{0, 0, 0, 255};
    const Texture st(stripes);
    const UvDerivatives long_u{32.0f / 256.0f, 0.0f, 0.0f, 4.0f / 256.0f}, sharp{4.0f / 256.0f, 0.0f, 0.0f, 4.0f / 256.0f};
    float aniso_contrast = 0.0f, tri_contrast = 0.0f;
    for (int k = 0; k < 64; ++k) {
        const glm::vec2 uv(0.37f, (float(k) + 0.3f) / 64.0f);
        const float got = st.sample(uv, long_u, aniso).r;
        EXPECT_NEAR(got, st.sample(uv, sharp, tri).r, 1e-6f) << k;
        aniso_contrast = std::max(aniso_contrast, std::abs(got - 0.5f));
        tri_contrast = std::max(tri_contrast, std::abs(st.sample(uv, long_u, tri).r - 0.5f));
    }
    EXPECT_GT(aniso_contrast, 0.3f);  // the stripes survive
    EXPECT_LT(tri_contrast, 0.05f);   // trilinear's level 5 has averaged them to gray
}

// Textures of the size of real assets' (a megapixel, one side not a power of two): every
// texel is where the image has it, and lookups at texel centers, eight at once, return it.
TEST(Texture, LargeTexturesKeepEveryTexel) {
    for (const auto& [w, h] : {std::pair{1024, 600}, std::pair{1024, 1024}}) {
        Image img(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) img.at(x, y) = {uint8_t(x), uint8_t(x >> 8 | y << 2), uint8_t(y), uint8_t(y >> 8 | 0x80)};
        const Texture t(img);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const Rgba8 want = img.at(i, h - 1 - j), got = t.stored(0, i, j);
                ASSERT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b && got.a == want.a) << w << "x" << h << " texel " << i << "," << j;
            }
        // Lookups at texel centers, eight at once, give the texels.
        const Sampler s = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
        for (int j = 0; j < h; j += 37) {
            simd::f8 u, v;
            for (int l = 0; l < simd::kLanes; ++l) u[l] = (float(l * 131 % w) + 0.5f) / float(w), v[l] = (float(j) + 0.5f) / float(h);
            std::array<simd::f8, 4> got;
            t.sample8(u, v, {}, s, got);
            for (int l = 0; l < simd::kLanes; ++l)
                ASSERT_EQ(got[0][l], t.texel(l * 131 % w, j).r) << w << "x" << h << " lane " << l << " row " << j;
        }
    }
}
