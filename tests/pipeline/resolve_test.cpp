// Stage 13, resolve (src/pipeline/resolve.cpp): each pixel's samples averaged, in linear
// light for an sRGB buffer, and the supersampling box filter.
#include <gtest/gtest.h>

#include <random>

#include "softraster/pipeline/resolve.h"
#include "softraster/srgb.h"
#include "softraster/worker_pool.h"
#include "test_support.h"

using namespace softraster;

// The sRGB resolve and the supersampling filter average in linear light: half the samples
// white and half black resolve to 188 (linear buffers: 128).
TEST(Resolve, SrgbAveragesInLinearLight) {
    for (int n : {2, 4, 8, 16}) {
        for (ColorSpace space : {ColorSpace::Linear, ColorSpace::Srgb}) {
            Framebuffer fb(3, 1, n, space);
            for (int s = 0; s < n; ++s) fb.color_data()[fb.sample_index(1, 0, s)] = s % 2 ? Rgba8{255, 255, 255, 255} : Rgba8{0, 0, 0, 0};
            const Image img = fb.read_pixels();
            EXPECT_EQ(img.at(1, 0), space == ColorSpace::Srgb ? (Rgba8{188, 188, 188, 128}) : (Rgba8{128, 128, 128, 128})) << n;
            EXPECT_EQ(img.at(0, 0), (Rgba8{}));
        }
    }
    Image big(2, 2);
    big.at(0, 0) = big.at(1, 1) = {255, 255, 255, 255};
    EXPECT_EQ(downsample_box(big, 2, ColorSpace::Srgb).at(0, 0), (Rgba8{188, 188, 188, 128}));
    EXPECT_EQ(downsample_box(big, 2).at(0, 0), (Rgba8{128, 128, 128, 128}));
}

// A pixel whose samples are all one color resolves to that color (which resolve takes as it
// is, without averaging): n equal values' sRGB mean, decoded, summed, scaled and encoded,
// gives the value back for every 8-bit value and sample count.
TEST(Resolve, EqualSamplesKeepTheirColor) {
    for (unsigned n : {2u, 4u, 8u, 16u})
        for (int k = 0; k < 256; ++k) {
            float sum = 0.0f;
            for (unsigned i = 0; i < n; ++i) sum += srgb::decode(uint8_t(k));
            ASSERT_EQ(srgb::encode(sum * (1.0f / float(n))), k) << n;
        }
}

// Each pixel is floor(mean + 0.5) of its samples per channel (r, g, b of decoded values in an
// sRGB buffer), computed here one pixel at a time, and the same with threads sharing the rows.
TEST(Resolve, EachPixelIsItsSamplesMeanWithOrWithoutThreads) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> byte(0, 255);
    WorkerPool pool(3);
    for (int n : {2, 4, 8})
        for (ColorSpace space : {ColorSpace::Linear, ColorSpace::Srgb}) {
            Framebuffer fb(70, 45, n, space);
            for (int y = 0; y < fb.height(); ++y)
                for (int x = 0; x < fb.width(); ++x) {
                    const Rgba8 one{uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng))};
                    // Every sample the same (as inside a triangle), each its own, or all but one the same.
                    for (int s = 0; s < n; ++s) {
                        const bool own = x % 3 == 1 || (x % 3 == 2 && s == (x / 3 + y) % n);
                        fb.color_data()[fb.sample_index(x, y, s)] =
                            own ? Rgba8{uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng))} : one;
                    }
                }
            Image alone, shared;
            resolve(fb, alone);
            resolve(fb, shared, &pool);
            ASSERT_EQ(alone.pixels, shared.pixels) << n;
            for (int y = 0; y < fb.height(); ++y)
                for (int x = 0; x < fb.width(); ++x) {
                    // sRGB: the decoded values summed as floats in sample order, times 1/n, encoded.
                    float linear[3] = {0, 0, 0};
                    unsigned sum[3] = {0, 0, 0}, a = 0;
                    for (int s = 0; s < n; ++s) {
                        const Rgba8 c = fb.color_data()[fb.sample_index(x, y, s)];
                        const uint8_t ch[3] = {c.r, c.g, c.b};
                        for (int i = 0; i < 3; ++i) linear[i] += srgb::decode(ch[i]), sum[i] += ch[i];
                        a += c.a;
                    }
                    const Rgba8 got = alone.at(x, y);
                    const uint8_t out[3] = {got.r, got.g, got.b};
                    for (int i = 0; i < 3; ++i) {
                        if (space == ColorSpace::Srgb) ASSERT_EQ(out[i], srgb::encode(linear[i] * (1.0f / float(n)))) << x << " " << y;
                        else ASSERT_EQ(out[i], (sum[i] + unsigned(n) / 2) / unsigned(n)) << x << " " << y;
                    }
                    ASSERT_EQ(got.a, (a + unsigned(n) / 2) / unsigned(n)) << x << " " << y;
                }
        }
}
