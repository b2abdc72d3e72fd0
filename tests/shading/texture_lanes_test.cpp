// The eight-lane lookups (src/shading/texture_lanes.cpp, texture_uniform.cpp) against the
// one-point lookups that define every result, bit for bit, on both CPU paths.
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "softraster/shading/texture.h"
#include "texture_test_support.h"

using namespace softraster;
using namespace softraster::test;

// sample8 (eight lanes, gathers, a level per lane) gives the bits of sample() lane by lane,
// on both code paths: every filter, mip mode and wrap pair, sizes that are not multiples of
// the 4x4 storage tiles, derivatives from far magnified to far minified, and coordinates
// that are huge, negative or not numbers.
TEST(Texture, EightLookupsAtOnceEqualOneAtATime) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f), log_scale(-12.0f, 4.0f), unit(-1.0f, 1.0f);
    const float odd[] = {NAN, INFINITY, -INFINITY, 3e38f, -2e7f, 1.0f, 0.0f, -0.0f};
    for (const auto& [w, h, color] : {std::tuple{37, 21, ColorSpace::Linear}, std::tuple{64, 64, ColorSpace::Linear},
                                      std::tuple{1, 5, ColorSpace::Linear}, std::tuple{37, 21, ColorSpace::Srgb}}) {
        const Texture t = pattern_texture(w, h, color);
        for (bool generic : {false, true}) {
            simd::use_generic_path(generic);
            for (Filter mag : {Filter::Nearest, Filter::Bilinear})
                for (Filter min : {Filter::Nearest, Filter::Bilinear})
                    for (MipFilter mip : {MipFilter::None, MipFilter::Nearest, MipFilter::Linear})
                        for (Wrap ws : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror, Wrap::Border})
                            for (Wrap wt : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror, Wrap::Border})
                              for (int aniso : {1, 5, 16}) {
                                const Sampler s{mag, min, mip, ws, wt, glm::vec4(0.1f, 0.3f, 0.5f, 0.7f), aniso};
                                for (int trial = 0; trial < 12; ++trial) {
                                    simd::f8 u, v;
                                    std::array<simd::f8, 4> d;
                                    for (int l = 0; l < simd::kLanes; ++l) {
                                        u[l] = trial == 0 ? odd[l] : coord(rng);
                                        v[l] = trial == 1 ? odd[7 - l] : coord(rng);
                                        const float scale = std::exp2(log_scale(rng));  // a quad per pair of lanes
                                        for (auto& dk : d) dk[l] = l % 2 ? dk[l - 1] : scale * unit(rng);
                                        if (trial >= 10 && l > 0)  // all lanes one footprint: one level for all
                                            for (auto& dk : d) dk[l] = dk[0];
                                    }
                                    expect_eight_equal_one_at_a_time(
                                        t, s, u, v, d,
                                        std::to_string(w) + "x" + std::to_string(h) + " generic " + std::to_string(generic) + " mag " + std::to_string(int(mag)) +
                                            " min " + std::to_string(int(min)) + " mip " + std::to_string(int(mip)) + " wrap " + std::to_string(int(ws)) + "," +
                                            std::to_string(int(wt)) + " aniso " + std::to_string(aniso));
                                }
                            }
        }
        simd::use_generic_path(false);
    }
}

// The common case has a path of its own (sample_uniform, and sample_uniform_srgb for sRGB
// textures: a power-of-two texture that repeats, bilinear both ways, every lane on the same
// levels): it too gives sample()'s bits, on each CPU path (its AVX-512 copy too, where the
// CPU has it), on square and long textures
// (whose levels stop halving one side at 1), for footprints from far below a texel to far
// past the last level, and for coordinates of any size.
TEST(Texture, UniformLookupsOnPowerOfTwoTexturesEqualOneAtATime) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(-40.0f, 40.0f), log_scale(-14.0f, 3.0f), unit(-1.0f, 1.0f), jitter(0.97f, 1.03f);
    auto check = [&](const Texture& t, const Sampler& s, int trial, const char* path) {
        simd::f8 u, v;
        std::array<simd::f8, 4> d;
        const float scale = std::exp2(log_scale(rng));
        const float base[4] = {scale * unit(rng), scale * unit(rng), scale * unit(rng), scale * unit(rng)};
        for (int l = 0; l < simd::kLanes; ++l) {
            u[l] = trial % 7 == 0 ? coord(rng) * 1.0e4f : coord(rng), v[l] = coord(rng);
            for (size_t k = 0; k < 4; ++k) d[k][l] = base[k] * (trial % 2 ? 1.0f : jitter(rng));  // (neighbours: mostly one level)
        }
        expect_eight_equal_one_at_a_time(t, s, u, v, d,
                                         std::to_string(t.width()) + "x" + std::to_string(t.height()) + (t.srgb() ? " srgb " : " ") + path + " mip " +
                                             std::to_string(int(s.mip)) + " trial " + std::to_string(trial));
    };
    for (const auto& [w, h, color] : {std::tuple{64, 64, ColorSpace::Linear}, std::tuple{128, 8, ColorSpace::Linear}, std::tuple{2, 256, ColorSpace::Linear},
                                      std::tuple{1, 1, ColorSpace::Linear}, std::tuple{64, 64, ColorSpace::Srgb}, std::tuple{128, 8, ColorSpace::Srgb},
                                      std::tuple{1, 1, ColorSpace::Srgb}}) {
        const Texture t = pattern_texture(w, h, color);
        for_each_cpu_path([&](const std::string& path) {
            for (MipFilter mip : {MipFilter::None, MipFilter::Nearest, MipFilter::Linear})
                for (int trial = 0; trial < 400; ++trial)
                    check(t, Sampler{Filter::Bilinear, Filter::Bilinear, mip, Wrap::Repeat, Wrap::Repeat, glm::vec4(0.0f), 1}, trial, path.c_str());
        });
    }
}

// The common lookup reads the levels the thread's last lookup read before it knows its own
// (texture_uniform.cpp): after a large texture's coarse levels, a small texture that has no
// such levels, and a lookup of one level after one of two, still read what they should.
TEST(Texture, UniformLookupsAfterOtherLevelsEqualOneAtATime) {
    const Texture large = pattern_texture(1024, 1024), small = pattern_texture(4, 4);
    const Sampler s{Filter::Bilinear, Filter::Bilinear, MipFilter::Linear, Wrap::Repeat, Wrap::Repeat, glm::vec4(0.0f), 1};
    auto lookups = [&](const Texture& t, float texels_per_pixel, const std::string& what) {
        simd::f8 u, v;
        for (int l = 0; l < simd::kLanes; ++l) u[l] = 0.3f + 0.01f * float(l), v[l] = 0.7f - 0.003f * float(l);
        const float d = texels_per_pixel / float(t.width());
        expect_eight_equal_one_at_a_time(t, s, u, v, {simd::splat(d), simd::splat(0.0f), simd::splat(0.0f), simd::splat(d)}, what);
    };
    for_each_cpu_path([&](const std::string& path) {
        lookups(large, 300.0f, "large, levels 8 and 9 " + path);
        lookups(small, 0.5f, "small, magnified " + path);
        lookups(large, 2.0f, "large, level 1 alone " + path);
        lookups(large, 2.5f, "large, levels 1 and 2 " + path);
        lookups(large, 2.0f, "large, level 1 alone again " + path);
    });
}

namespace {
// The cases of the tests of lookups in groups (sample_pair, sample_four): f(texture,
// sampler, trial, what) for linear and sRGB textures, power-of-two sides or not, on each CPU
// path, each mip filter and wrap mode, 150 trials each; it stops at the first failure.
template <class F>
void for_each_grouped_lookup_case(F&& f) {
    for (const auto& [w, h, color] : {std::tuple{64, 64, ColorSpace::Linear}, std::tuple{128, 8, ColorSpace::Linear}, std::tuple{1, 1, ColorSpace::Linear},
                                      std::tuple{48, 32, ColorSpace::Linear}, std::tuple{64, 64, ColorSpace::Srgb}}) {
        const Texture t = pattern_texture(w, h, color);
        for_each_cpu_path([&](const std::string& path) {
            for (MipFilter mip : {MipFilter::None, MipFilter::Nearest, MipFilter::Linear})
                for (Wrap wrap : {Wrap::Repeat, Wrap::Clamp})
                    for (int trial = 0; trial < 150; ++trial) {
                        Sampler s = Sampler::plain(Filter::Bilinear, wrap);
                        s.mip = mip;
                        f(t, s, trial, std::to_string(w) + "x" + std::to_string(h) + " trial " + std::to_string(trial) + " " + path);
                        if (::testing::Test::HasFatalFailure()) return;
                    }
        });
        if (::testing::Test::HasFatalFailure()) return;
    }
}
// Now and then coordinates far from the texture (up to 4 10^5, whose fractions the wrap must
// still find), or past where the lookups take them as 0 (10^6), or not numbers at all: the
// grouped lookups reduce them on their own (texture_uniform.cpp), not as sample8 does.
void far_and_odd_coordinates(int trial, simd::f8& u, simd::f8& v) {
    const float odd[] = {NAN, INFINITY, -INFINITY, 3e38f, -2e7f, -5e5f, 1.5e6f, -0.0f};
    if (trial % 7 == 3) u = u * 1.0e4f, v = v * -1.0e4f;
    if (trial % 11 == 5)
        for (int l = 0; l < simd::kLanes; ++l) u[l] = odd[l], v[l] = odd[7 - l];
}
// got and want the same bits in every lane and channel.
void expect_same_lookups(const std::array<simd::f8, 4>& got, const std::array<simd::f8, 4>& want, const std::string& what) {
    for (int l = 0; l < simd::kLanes; ++l)
        for (size_t k = 0; k < 4; ++k) ASSERT_EQ(std::bit_cast<uint32_t>(got[k][l]), std::bit_cast<uint32_t>(want[k][l])) << what << " lane " << l;
}
}  // namespace

// Four groups at once (sample_four: two neighbouring pairs of a row of quads, or any four)
// give what each gives alone (sample8): one level of detail where both pairs take the same
// levels, each pair its own where they do not, each group its own where a pair's rows'
// derivatives differ.
TEST(Texture, FourGroupLookupsEqualEightAtATime) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> coord(-40.0f, 40.0f), log_scale(-14.0f, 3.0f), unit(-1.0f, 1.0f), near(-0.02f, 0.02f);
    for_each_grouped_lookup_case([&](const Texture& t, const Sampler& s, int trial, const std::string& what) {
        simd::f8 u[4], v[4];
        std::array<simd::f8, 4> d[4];
        const float scale = std::exp2(log_scale(rng));
        // (the second pair: mostly the same scale, as neighbours are; now and then a level or more apart)
        const float scale2 = trial % 4 == 0 ? scale * std::exp2(2.0f * unit(rng)) : scale;
        for (int l = 0; l < simd::kLanes; ++l) {
            u[0][l] = coord(rng), v[0][l] = coord(rng), u[1][l] = u[0][l] + near(rng), v[1][l] = v[0][l] + near(rng);
            u[2][l] = u[0][l] + 8.0f * scale, v[2][l] = v[0][l] + near(rng), u[3][l] = u[2][l] + near(rng), v[3][l] = v[2][l] + near(rng);
            for (size_t k = 0; k < 4; ++k) {
                const float slant = trial % 3 ? 1.0f : unit(rng);
                d[0][k][l] = scale * slant, d[2][k][l] = scale2 * slant;
            }
        }
        d[1] = d[0], d[3] = d[2];
        if (trial % 5 == 0) d[3][1] = d[3][1] * 1.5f;  // (not the same quads)
        if (trial % 5 == 1)  // any four groups (the fragment queue's): elsewhere, footprints up to a level or two apart
            for (size_t g = 1; g < 4; ++g) {
                const float apart = std::exp2(2.0f * unit(rng));
                for (int l = 0; l < simd::kLanes; ++l) {
                    u[g][l] = coord(rng), v[g][l] = coord(rng);
                    for (size_t k = 0; k < 4; ++k) d[g][k][l] = d[0][k][l] * apart * (1.0f + 0.1f * unit(rng));
                }
            }
        for (size_t g = 0; g < 4; ++g) far_and_odd_coordinates(trial, u[g], v[g]);
        std::array<simd::f8, 4> got[4], want[4];
        std::array<simd::f8, 6> in[4];  // (u, v, d in a row, as a shader's varyings hold them)
        for (size_t g = 0; g < 4; ++g) in[g] = {u[g], v[g], d[g][0], d[g][1], d[g][2], d[g][3]};
        const simd::f8* const at[4] = {in[0].data(), in[1].data(), in[2].data(), in[3].data()};
        t.sample_four(at, s, got);
        for (int g = 0; g < 4; ++g) t.sample8(u[g], v[g], d[g], s, want[g]);
        for (int g = 0; g < 4; ++g) expect_same_lookups(got[g], want[g], what + " group " + std::to_string(g));
    });
}

// Two groups at once (sample_pair: a row of quads' two rows, or any two, as the fragment
// queue's groups) give what each gives alone (sample8): sharing the level of detail where
// their derivatives are the same (the quads'), each its own where they differ; linear and
// sRGB, power-of-two sides or not, any sampler.
TEST(Texture, PairLookupsEqualEightAtATime) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> coord(-40.0f, 40.0f), log_scale(-14.0f, 3.0f), unit(-1.0f, 1.0f), near(-0.02f, 0.02f);
    for_each_grouped_lookup_case([&](const Texture& t, const Sampler& s, int trial, const std::string& what) {
        simd::f8 u0, v0, u1, v1;
        std::array<simd::f8, 4> d0, d1;
        const float scale = std::exp2(log_scale(rng));
        for (int l = 0; l < simd::kLanes; ++l) {
            u0[l] = coord(rng), v0[l] = coord(rng), u1[l] = u0[l] + near(rng), v1[l] = v0[l] + near(rng);
            for (size_t k = 0; k < 4; ++k) d0[k][l] = scale * (trial % 3 ? 1.0f : unit(rng));
        }
        d1 = d0;
        if (trial % 5 == 0) d1[1] = d1[1] * 1.5f;  // (not the same quads)
        if (trial % 5 == 1) {  // any two groups: elsewhere, footprints up to a level or two apart
            const float apart = std::exp2(2.0f * unit(rng));
            for (int l = 0; l < simd::kLanes; ++l) {
                u1[l] = coord(rng), v1[l] = coord(rng);
                for (size_t k = 0; k < 4; ++k) d1[k][l] = d0[k][l] * apart * (1.0f + 0.1f * unit(rng));
            }
        }
        far_and_odd_coordinates(trial, u0, v0), far_and_odd_coordinates(trial, u1, v1);
        std::array<simd::f8, 4> got0, got1, want0, want1;
        t.sample_pair(u0, v0, u1, v1, d0, d1, s, got0, got1);
        t.sample8(u0, v0, d0, s, want0);
        t.sample8(u1, v1, d1, s, want1);
        expect_same_lookups(got0, want0, what + " first row");
        expect_same_lookups(got1, want1, what + " second row");
    });
}

