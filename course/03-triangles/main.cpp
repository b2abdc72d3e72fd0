// Lesson 3: filling triangles. One triangle filled three ways (bounding box with barycentric
// coordinates, edge functions with the fill rule, scanline), and a mesh whose triangles share
// edges through pixel centers, drawn with and without the fill rule, counting the hits.
#include <vector>

#include "../common/canvas.h"
#include "../common/lesson.h"
#include "fill.h"

using namespace course;

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    constexpr int kSize = 32;
    // A triangle with its corners anywhere (in 1/256 pixel): 2.3, 3.1 / 29.6, 11.8 / 9.2, 29.4.
    const Point a{589, 794}, b{7578, 3021}, c{2355, 7526};
    Canvas bary(kSize, kSize), edges(kSize, kSize), scan(kSize, kSize);
    fill_barycentric(a, b, c, kSize, kSize, [&](int x, int y) { bary.set(x, y, kYellow); });
    fill_edge_functions(a, b, c, kSize, kSize, [&](int x, int y) { edges.set(x, y, kGreen); });
    fill_scanline(a, b, c, kSize, kSize, [&](int x, int y) { scan.set(x, y, kBlue); });
    beside({&bary, &edges, &scan}).save(out / "three_ways.png", 6);
    wrote(out / "three_ways.png");

    // A grid of 4 x 3 squares, 7 pixels a side, corners on pixel centers, each square cut
    // along a diagonal; and a fan of 8 triangles around a center. Every shared edge runs
    // through pixel centers. Count how often each pixel is drawn: gray once, red twice or
    // more, and nothing where no triangle reaches.
    struct Triangle {
        Point a, b, c;
    };
    std::vector<Triangle> mesh;
    for (int gy = 0; gy < 3; ++gy)
        for (int gx = 0; gx < 4; ++gx) {
            const Point p00 = pixel_center(1 + 7 * gx, 1 + 7 * gy), p10 = pixel_center(8 + 7 * gx, 1 + 7 * gy),
                        p01 = pixel_center(1 + 7 * gx, 8 + 7 * gy), p11 = pixel_center(8 + 7 * gx, 8 + 7 * gy);
            mesh.push_back({p00, p10, p11});
            mesh.push_back({p00, p11, p01});
        }
    const Point center = pixel_center(44, 11);
    const Point ring[8] = {pixel_center(44, 1), pixel_center(52, 3), pixel_center(54, 11), pixel_center(52, 19),
                           pixel_center(44, 21), pixel_center(36, 19), pixel_center(34, 11), pixel_center(36, 3)};
    for (int k = 0; k < 8; ++k) mesh.push_back({center, ring[k], ring[(k + 1) % 8]});
    auto count_hits = [&](auto fill) {
        constexpr int kW = 57, kH = 24;
        std::vector<int> hits(kW * kH, 0);
        for (const Triangle& t : mesh) fill(t.a, t.b, t.c, kW, kH, [&](int x, int y) { ++hits[size_t(y * kW + x)]; });
        Canvas picture(kW, kH);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (int n = hits[size_t(y * kW + x)]; n > 0) picture.set(x, y, n == 1 ? kGray : kRed);
        return picture;
    };
    const Canvas without = count_hits([](auto... args) { fill_barycentric(args...); });
    const Canvas with = count_hits([](auto... args) { fill_edge_functions(args...); });
    beside({&without, &with}, 3).save(out / "shared_edges.png", 6);
    wrote(out / "shared_edges.png");
    return 0;
}
