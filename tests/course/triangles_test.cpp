// Lesson 3 (course/03-triangles): the scanline fill and the edge-function fill cover exactly
// the pixels the production rasterizer covers (include/softraster/pipeline/rasterization.h,
// top-left rule), on thousands of random triangles and on meshes of triangles that share
// edges, where the fill rule draws every pixel once: no gaps, no double hits. Barycentric
// coordinates without a rule differ only on centers that lie exactly on an edge.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "course/03-triangles/fill.h"
#include "course/common/pipeline.h"

using namespace course;

namespace {

constexpr int kSize = 64;  // (a power of two: positions come through clip space exactly)

template <class Fill>
std::vector<int> hits(Fill fill, Point a, Point b, Point c) {
    std::vector<int> out(kSize * kSize, 0);
    fill(a, b, c, kSize, kSize, [&](int x, int y) { ++out[size_t(y * kSize + x)]; });
    return out;
}

std::vector<int> pipeline_hits(std::span<const Point> corners) {
    std::vector<PixelVertex> v;
    for (const Point& p : corners) v.push_back({{float(p.x) / kSub, float(p.y) / kSub}});
    const std::vector<bool> covered = pipeline_coverage(kSize, kSize, softraster::Topology::Triangles, v);
    return std::vector<int>(covered.begin(), covered.end());
}

}  // namespace

TEST(CourseTriangles, ScanlineEdgeFunctionsAndThePipelineCoverTheSamePixels) {
    std::mt19937 rng(3);
    // Corners anywhere on the subpixel grid, sometimes on pixel centers and shared lines (so
    // that centers fall exactly on edges, where the fill rule decides).
    std::uniform_int_distribution<int64_t> anywhere(0, kSize * kSub - 1), center(0, kSize - 1);
    size_t on_edges = 0;
    for (int n = 0; n < 3000; ++n) {
        Point p[3];
        for (Point& q : p) q = n % 2 ? Point{anywhere(rng), anywhere(rng)} : pixel_center(int(center(rng)), int(center(rng)));
        const auto edges = hits([](auto... a) { fill_edge_functions(a...); }, p[0], p[1], p[2]);
        const auto scan = hits([](auto... a) { fill_scanline(a...); }, p[0], p[1], p[2]);
        const auto bary = hits([](auto... a) { fill_barycentric(a...); }, p[0], p[1], p[2]);
        ASSERT_EQ(scan, edges) << "triangle " << n;
        ASSERT_EQ(pipeline_hits(p), edges) << "triangle " << n;
        for (int i = 0; i < kSize * kSize; ++i) {
            if (bary[size_t(i)] == edges[size_t(i)]) continue;
            // Only where a center lies exactly on an edge, and only as extra pixels.
            const Point c = pixel_center(i % kSize, i / kSize);
            ASSERT_TRUE(bary[size_t(i)] == 1 && (edge_function(p[0], p[1], c) == 0 || edge_function(p[1], p[2], c) == 0 ||
                                                 edge_function(p[2], p[0], c) == 0));
            ++on_edges;
        }
    }
    EXPECT_GT(on_edges, 100u);  // (the cases the rule is for did come up)
}

TEST(CourseTriangles, SharedEdgesAreDrawnOnce) {
    std::mt19937 rng(4);
    for (int n = 0; n < 60; ++n) {
        // A grid of 6 x 6 cells of 8 pixels, each inner corner moved at random (on pixel
        // centers every other mesh, so that edges run through centers), each cell cut along
        // a diagonal chosen at random.
        constexpr int kCells = 6, kCell = 8;
        // (At most 1.5 pixels: a corner never crosses the diagonal of a cell it belongs to, which
        // would fold a triangle over its neighbour.)
        std::uniform_int_distribution<int64_t> jitter(-3 * kSub / 2, 3 * kSub / 2), pixels(-1, 1);
        Point corner[kCells + 1][kCells + 1];
        for (int j = 0; j <= kCells; ++j)
            for (int i = 0; i <= kCells; ++i) {
                Point p = pixel_center(4 + kCell * i, 4 + kCell * j);
                if (i > 0 && j > 0 && i < kCells && j < kCells) {
                    if (n % 2) p.x += jitter(rng), p.y += jitter(rng);
                    else p.x += kSub * pixels(rng), p.y += kSub * pixels(rng);
                }
                corner[j][i] = p;
            }
        std::vector<int> total(kSize * kSize, 0), gpu_total(kSize * kSize, 0);
        std::vector<Point> all;
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) {
                const Point a = corner[j][i], b = corner[j][i + 1], c = corner[j + 1][i + 1], d = corner[j + 1][i];
                const bool flip = rng() & 1;
                const Point tris[2][3] = {{a, b, flip ? d : c}, {flip ? b : a, c, d}};
                for (const auto& t : tris) {
                    const auto h = hits([](auto... x) { fill_scanline(x...); }, t[0], t[1], t[2]);
                    for (size_t k = 0; k < h.size(); ++k) total[k] += h[k];
                    all.insert(all.end(), t, t + 3);
                }
            }
        // Each pixel at most once; every pixel whose center is inside the grid's outline
        // (its border is straight: the outer corners did not move) exactly once.
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const int h = total[size_t(y * kSize + x)];
                ASSERT_LE(h, 1) << "mesh " << n << " pixel " << x << "," << y;
                const bool inside = x >= 4 && x < 4 + kCells * kCell && y >= 4 && y < 4 + kCells * kCell;
                ASSERT_EQ(h, inside ? 1 : 0) << "mesh " << n << " pixel " << x << "," << y;
            }
        // The pipeline, drawing the whole mesh, covers the same pixels.
        const auto gpu = pipeline_hits(all);
        for (size_t k = 0; k < total.size(); ++k) ASSERT_EQ(gpu[k], total[k]) << "mesh " << n;
    }
}
