// Lesson 1 (course/01-lines): DDA and Bresenham choose the same pixels except where the line
// passes exactly between two (a tie), and the production pipeline's lines (OpenGL's diamond
// exit, include/softraster/pipeline/line_point_quads.h) are Bresenham's without the last
// pixel, again up to ties.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "course/01-lines/lines.h"
#include "course/common/pipeline.h"

using namespace course;

namespace {

struct Pixel {
    int x, y;
    friend bool operator==(const Pixel&, const Pixel&) = default;
};

template <class Line>
std::vector<Pixel> pixels_of(Line line, int x0, int y0, int x1, int y1) {
    std::vector<Pixel> out;
    line(x0, y0, x1, y1, [&](int x, int y) { out.push_back({x, y}); });
    return out;
}

// The two pixels are the two nearest the line at a tie: one apart across the minor axis.
bool minor_neighbours(const Pixel& a, const Pixel& b, bool steep) {
    return steep ? (a.y == b.y && std::abs(a.x - b.x) == 1) : (a.x == b.x && std::abs(a.y - b.y) == 1);
}

}  // namespace

TEST(CourseLines, DdaAndBresenhamDifferOnlyAtTies) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> coord(-40, 40);
    int ties = 0;
    for (int n = 0; n < 20000; ++n) {
        const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
        const auto dda = pixels_of([](auto... a) { line_dda(a...); }, x0, y0, x1, y1);
        const auto bre = pixels_of([](auto... a) { line_bresenham(a...); }, x0, y0, x1, y1);
        ASSERT_EQ(dda.size(), bre.size());
        const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
        for (size_t k = 0; k < dda.size(); ++k) {
            if (dda[k] == bre[k]) continue;
            ASSERT_TRUE(line_tie_at(x0, y0, x1, y1, int(k))) << x0 << "," << y0 << " -> " << x1 << "," << y1 << " step " << k;
            ASSERT_TRUE(minor_neighbours(dda[k], bre[k], steep));
            ++ties;
        }
        ASSERT_EQ(bre.front(), (Pixel{x0, y0}));
        ASSERT_EQ(bre.back(), (Pixel{x1, y1}));
    }
    EXPECT_GT(ties, 100);  // (the ties do happen, and differently)
}

TEST(CoursePipeline, LinesAreBresenhamWithoutTheLastPixel) {
    constexpr int kSize = 64;  // (a power of two: pixel positions survive the trip through clip space exactly)
    std::mt19937 rng(2);
    std::uniform_int_distribution<int> coord(0, kSize - 1);
    for (int n = 0; n < 1500; ++n) {
        const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
        if (x0 == x1 && y0 == y1) continue;
        const PixelVertex ends[] = {{{x0 + 0.5f, y0 + 0.5f}}, {{x1 + 0.5f, y1 + 0.5f}}};
        const std::vector<bool> gpu = pipeline_coverage(kSize, kSize, softraster::Topology::Lines, ends);
        const auto bre = pixels_of([](auto... a) { line_bresenham(a...); }, x0, y0, x1, y1);
        const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
        size_t covered = 0;
        for (bool c : gpu) covered += c;
        ASSERT_EQ(covered, bre.size() - 1) << x0 << "," << y0 << " -> " << x1 << "," << y1;  // one per column, the last left out
        for (size_t k = 0; k + 1 < bre.size(); ++k) {
            const Pixel p = bre[k];
            if (gpu[size_t(p.y * kSize + p.x)]) continue;
            ASSERT_TRUE(line_tie_at(x0, y0, x1, y1, int(k))) << x0 << "," << y0 << " -> " << x1 << "," << y1 << " step " << k;
            const Pixel other = steep ? Pixel{p.x + (x1 > x0 ? 1 : -1), p.y} : Pixel{p.x, p.y + (y1 > y0 ? 1 : -1)};
            ASSERT_TRUE(minor_neighbours(p, other, steep));
            ASSERT_TRUE(gpu[size_t(other.y * kSize + other.x)]);
        }
        ASSERT_FALSE(gpu[size_t(bre.back().y * kSize + bre.back().x)]);
    }
}
