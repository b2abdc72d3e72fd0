// Lesson 5 (course/05-depth): the painter's algorithm and the z-buffer draw the same picture
// where no triangles intersect and each lies at one depth (layers parallel to the screen);
// the z-buffer's picture does not depend on the order of drawing, the painter's does not
// either once sorted, and with intersecting triangles the two differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "course/05-depth/depth.h"

using namespace course;

namespace {

constexpr int kSize = 48;

std::vector<ScreenTriangle> random_triangles(std::mt19937& rng, int count, bool layers) {
    std::uniform_int_distribution<int64_t> coord(0, kSize * kSub - 1);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    std::uniform_int_distribution<int> channel(30, 255);
    std::vector<ScreenTriangle> out;
    for (int i = 0; i < count; ++i) {
        ScreenTriangle t{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, depth(rng), depth(rng), depth(rng),
                         {uint8_t(channel(rng)), uint8_t(channel(rng)), uint8_t(i)}};
        if (layers) t.zb = t.zc = t.za = float(i + 1) / float(count + 1);  // one depth each, all different
        out.push_back(t);
    }
    return out;
}

std::vector<Color> pixels(const Canvas& c) {
    std::vector<Color> out;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) out.push_back(c.get(x, y));
    return out;
}

}  // namespace

TEST(CourseDepth, PainterEqualsZBufferForLayers) {
    std::mt19937 rng(6);
    for (int n = 0; n < 300; ++n) {
        auto triangles = random_triangles(rng, 8, true);
        std::shuffle(triangles.begin(), triangles.end(), rng);
        Canvas painter(kSize, kSize), zbuffer(kSize, kSize);
        draw_painter(triangles, painter);
        draw_z_buffer(triangles, zbuffer);
        ASSERT_EQ(pixels(painter), pixels(zbuffer)) << n;
    }
}

TEST(CourseDepth, TheZBufferDoesNotCareAboutOrderThePainterFailsOnIntersections) {
    std::mt19937 rng(7);
    int painter_wrong = 0;
    for (int n = 0; n < 200; ++n) {
        auto triangles = random_triangles(rng, 6, false);
        Canvas first(kSize, kSize), shuffled(kSize, kSize), painter(kSize, kSize);
        draw_z_buffer(triangles, first);
        draw_painter(triangles, painter);
        std::shuffle(triangles.begin(), triangles.end(), rng);
        draw_z_buffer(triangles, shuffled);
        ASSERT_EQ(pixels(first), pixels(shuffled)) << n;
        painter_wrong += pixels(painter) != pixels(first);
    }
    EXPECT_GT(painter_wrong, 100);  // tilted, crossing triangles: most such scenes
}
