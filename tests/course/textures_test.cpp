// Lesson 12 (course/12-textures): nearest and bilinear lookups and the mipmap chain are the
// production texture's (include/softraster/shading/texture.h) on random coordinates.
#include <gtest/gtest.h>

#include <random>

#include "course/12-textures/texture.h"
#include "softraster/shading/texture.h"

using namespace course;

TEST(CourseTextures, LookupsAndMipmapsAreTheProductionTextures) {
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> byte(0, 255);
    for (const auto& [w, h] : {std::pair{64, 64}, std::pair{32, 8}, std::pair{1, 16}}) {
        TexelImage ours{w, h, {}};
        softraster::Image picture(w, h);  // row 0 at the top: the texture's row h - 1
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const glm::u8vec4 t(byte(rng), byte(rng), byte(rng), byte(rng));
                ours.texels.push_back(t);
            }
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const glm::u8vec4 t = ours.texels[size_t(j) * size_t(w) + size_t(i)];
                picture.at(i, h - 1 - j) = {t.r, t.g, t.b, t.a};
            }
        const softraster::Texture theirs(picture);
        std::uniform_real_distribution<float> coord(-2.0f, 3.0f);
        for (int n = 0; n < 5000; ++n) {
            const glm::vec2 uv(coord(rng), coord(rng));
            const glm::vec4 a = sample_nearest(ours, uv), b = theirs.sample(uv, softraster::Filter::Nearest, softraster::Wrap::Repeat);
            const glm::vec4 c = sample_bilinear(ours, uv), d = theirs.sample(uv, softraster::Filter::Bilinear, softraster::Wrap::Repeat);
            for (int k = 0; k < 4; ++k) {
                ASSERT_NEAR(a[k], b[k], 1e-6f) << uv.x << "," << uv.y;
                // softraster filters 8-bit textures in fixed point: its weights are cut to 1/256,
                // which moves a blend by under 1/256 per axis (texture.h "Precision").
                ASSERT_NEAR(c[k], d[k], 2.0f / 256.0f + 2.0f / 65280.0f) << uv.x << "," << uv.y;
            }
        }
        const std::vector<TexelImage> chain = mipmaps(ours);
        ASSERT_EQ(int(chain.size()), theirs.levels());
        for (int level = 0; level < theirs.levels(); ++level) {
            ASSERT_EQ(chain[size_t(level)].width, theirs.level_width(level));
            for (int j = 0; j < theirs.level_height(level); ++j)
                for (int i = 0; i < theirs.level_width(level); ++i) {
                    const glm::u8vec4 t = chain[size_t(level)].texels[size_t(j) * size_t(chain[size_t(level)].width) + size_t(i)];
                    const softraster::Rgba8 s = theirs.stored(level, i, j);
                    ASSERT_EQ(t, glm::u8vec4(s.r, s.g, s.b, s.a)) << "level " << level << " texel " << i << "," << j;
                }
        }
    }
}

TEST(CourseTextures, LevelOfDetailIsLog2OfTexelsPerPixel) {
    const TexelImage t{256, 256, std::vector<glm::u8vec4>(256 * 256)};
    EXPECT_FLOAT_EQ(level_of_detail(t, {1.0f / 256, 0}, {0, 1.0f / 256}), 0.0f);  // one texel per pixel
    EXPECT_FLOAT_EQ(level_of_detail(t, {4.0f / 256, 0}, {0, 1.0f / 256}), 2.0f);  // four along x: level 2
    EXPECT_FLOAT_EQ(level_of_detail(t, {0.5f / 256, 0}, {0, 0.5f / 256}), -1.0f); // magnified
}
