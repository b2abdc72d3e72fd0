// Texture sampling: orientation, nearest and bilinear filtering, repeat and clamp wrapping.
#include <gtest/gtest.h>

#include "softraster/shading/texture.h"

using namespace softraster;

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

TEST(Texture, NonFiniteCoordinatesAreSafe) {
    const Texture t = four_texels();
    for (float bad : {NAN, INFINITY, -INFINITY, 3e38f})
        for (Filter f : {Filter::Nearest, Filter::Bilinear})
            for (Wrap w : {Wrap::Repeat, Wrap::Clamp}) {
                const glm::vec4 c = t.sample(glm::vec2(bad, 0.5f), f, w);
                EXPECT_TRUE(c.a == 1.0f);
            }
}
