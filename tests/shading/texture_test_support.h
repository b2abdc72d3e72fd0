// What the texture tests share (texture_test.cpp, texture_lanes_test.cpp): a patterned
// texture, an isotropic footprint, and eight lookups at once checked against one at a time.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <string>

#include <gtest/gtest.h>

#include "softraster/shading/texture.h"

namespace softraster::test {

// w x h texels, every texel the same gray per level test below, or a pattern.
inline Texture pattern_texture(int w, int h, ColorSpace color = ColorSpace::Linear) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = {uint8_t(x * 255 / std::max(1, w - 1)), uint8_t(y * 37 % 256), uint8_t((x + y) % 2 ? 250 : 10), 255};
    return Texture(img, color);
}
inline UvDerivatives isotropic(float texels_per_pixel, int size) {
    const float d = texels_per_pixel / float(size);
    return {d, 0.0f, 0.0f, d};
}
// Eight lookups at once against sample(), lane by lane, bit for bit; `what` names the case.
inline void expect_eight_equal_one_at_a_time(const Texture& t, const Sampler& s, const simd::f8& u, const simd::f8& v, const std::array<simd::f8, 4>& d,
                                      const std::string& what) {
    std::array<simd::f8, 4> got;
    t.sample8(u, v, d, s, got);
    for (int l = 0; l < simd::kLanes; ++l) {
        const glm::vec4 want = t.sample(glm::vec2(u[l], v[l]), UvDerivatives{d[0][l], d[1][l], d[2][l], d[3][l]}, s);
        for (int k = 0; k < 4; ++k)
            ASSERT_EQ(std::bit_cast<uint32_t>(got[size_t(k)][l]), std::bit_cast<uint32_t>(want[k])) << what << " lane " << l << " uv " << u[l] << "," << v[l];
    }
}

// f(name) on each CPU path a lookup can take (pipeline/simd.h): the best this CPU has (the
// common lookup's AVX-512 copy where it runs), the AVX2 one, and the generic one; then the
// best again. (On a CPU without AVX-512 the first two are the same; without AVX2, all three.)
template <class F>
void for_each_cpu_path(F&& f) {
    for (const char* path : {"best", "avx2", "generic"}) {
        simd::use_avx512(path == std::string("best"));
        simd::use_generic_path(path == std::string("generic"));
        f(std::string(path));
        if (::testing::Test::HasFatalFailure()) break;
    }
    simd::use_avx512(true), simd::use_generic_path(false);
}

}  // namespace softraster::test
