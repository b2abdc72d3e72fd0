// The fill rule: meshes of many triangles that share edges, drawn with additive blending
// (each coverage adds 1/255), must cover every covered sample exactly once: no sample
// twice (double blending along shared edges) and none missing (cracks).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numbers>
#include <random>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 96, H = 80;

struct Mesh2D {
    std::vector<glm::vec2> points;  // window space, pixels
    std::vector<uint32_t> indices;
    std::vector<glm::vec2> hull;    // convex outline, for the expected coverage
};

// Additive blend of 1/255 per coverage; returns the count per sample.
std::vector<int> coverage_counts(const Mesh2D& m, int samples, std::mt19937& rng) {
    Framebuffer fb(W, H, samples);
    Context ctx(fb);
    count_coverage(ctx);
    std::uniform_real_distribution<float> wdist(0.5f, 3.0f);
    std::vector<ClipVertexIn> v;
    for (const glm::vec2& p : m.points) v.push_back({window_to_clip(p.x, p.y, W, H, 0.5f, wdist(rng)), 0});
    draw(ctx, ConstantColorShader{glm::vec4(1, 1, 1, 1.0f / 255.0f)}, v, m.indices);
    std::vector<int> counts(size_t(W) * H * size_t(samples));
    for (size_t i = 0; i < counts.size(); ++i) counts[i] = fb.color_data()[i].r;
    return counts;
}

// Signed distance of p inside the convex hull (positive inside), in pixels.
float inside_distance(const std::vector<glm::vec2>& hull, glm::vec2 p) {
    float d = 1e9f;
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const glm::vec2 e = glm::normalize(b - a);
        d = std::min(d, e.x * (p.y - a.y) - e.y * (p.x - a.x));  // hull is clockwise on screen
    }
    return d;
}

void expect_exactly_once(const Mesh2D& m, int samples, std::mt19937& rng) {
    const std::vector<int> counts = coverage_counts(m, samples, rng);
    static const float sx4[4] = {0.375f, 0.875f, 0.125f, 0.625f}, sy4[4] = {0.125f, 0.375f, 0.625f, 0.875f};
    int covered = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int s = 0; s < samples; ++s) {
                const int c = counts[(size_t(y) * W + size_t(x)) * size_t(samples) + size_t(s)];
                const glm::vec2 p = samples == 1 ? glm::vec2(x + 0.5f, y + 0.5f) : glm::vec2(x + sx4[s], y + sy4[s]);
                const float d = inside_distance(m.hull, p);
                ASSERT_LE(c, 1) << "sample covered twice at " << x << "," << y << " s" << s;
                if (d > 0.01f) {
                    ASSERT_EQ(c, 1) << "crack at " << x << "," << y << " s" << s;
                }
                if (d < -0.01f) {
                    ASSERT_EQ(c, 0) << "coverage outside the mesh at " << x << "," << y;
                }
                covered += c;
            }
    EXPECT_GT(covered, 100);
}

// Grid of (n x n) cells over a parallelogram, interior vertices jittered; random rotation,
// scale and sub-pixel offset.
Mesh2D grid(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(0, 1), jitter(-0.2f, 0.2f);  // small enough to keep every cell convex
    const float angle = u(rng) * 2 * std::numbers::pi_v<float>, scale = 50 + 20 * u(rng);
    const glm::vec2 center(W / 2 + u(rng), H / 2 + u(rng));
    const glm::mat2 rot(std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle));
    auto map = [&](glm::vec2 q) { return center + rot * ((q - 0.5f) * scale); };
    Mesh2D m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            glm::vec2 q(float(i) / n, float(j) / n);
            if (i > 0 && i < n && j > 0 && j < n) q += glm::vec2(jitter(rng), jitter(rng)) / float(n);
            m.points.push_back(map(q));
        }
    m.indices = grid_indices(n, [&](uint32_t) { return u(rng) < 0.5f; });
    std::vector<glm::vec2> corners = {map({0, 0}), map({1, 0}), map({1, 1}), map({0, 1})};
    // Make the hull clockwise on screen (y down).
    const glm::vec2 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0];
    if (e1.x * e2.y - e1.y * e2.x < 0) std::reverse(corners.begin(), corners.end());
    m.hull = corners;
    return m;
}

// A convex polygon with random corners on a circle, triangulated as a fan from an interior
// point, or by random diagonals.
Mesh2D polygon(std::mt19937& rng, bool fan) {
    std::uniform_real_distribution<float> u(0, 1);
    const int n = 5 + int(u(rng) * 20);
    // Jittered even angles: every gap is below pi, so the center stays inside the polygon.
    std::vector<float> angles(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) angles[size_t(i)] = (float(i) + 0.8f * u(rng)) / float(n) * 2 * std::numbers::pi_v<float>;
    const glm::vec2 center(W / 2 + u(rng), H / 2 + u(rng));
    const float r = 30 + 8 * u(rng);
    Mesh2D m;
    for (float a : angles) m.points.push_back(center + r * glm::vec2(std::cos(a), std::sin(a)));  // clockwise on screen
    m.hull = m.points;
    if (fan) {
        m.points.push_back(center + glm::vec2(u(rng) - 0.5f, u(rng) - 0.5f));
        for (int i = 0; i < n; ++i) m.indices.insert(m.indices.end(), {uint32_t(n), uint32_t(i), uint32_t((i + 1) % n)});
    } else {
        std::function<void(std::vector<uint32_t>)> split = [&](std::vector<uint32_t> poly) {
            if (poly.size() == 3) {
                m.indices.insert(m.indices.end(), poly.begin(), poly.end());
                return;
            }
            const size_t k = poly.size();
            const size_t i = size_t(u(rng) * float(k)) % k, j = (i + 2 + size_t(u(rng) * float(k - 3))) % k;
            std::vector<uint32_t> a, b;
            for (size_t t = i;; t = (t + 1) % k) {
                a.push_back(poly[t]);
                if (t == j) break;
            }
            for (size_t t = j;; t = (t + 1) % k) {
                b.push_back(poly[t]);
                if (t == i) break;
            }
            split(a);
            split(b);
        };
        std::vector<uint32_t> all(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) all[size_t(i)] = uint32_t(i);
        split(all);
    }
    return m;
}

// 30 meshes from make(rng, iteration), each checked with 1 and with 4 samples.
template <class Make>
void expect_exactly_once_for_30(unsigned seed, Make&& make) {
    std::mt19937 rng(seed);
    for (int iter = 0; iter < 30; ++iter) {
        const Mesh2D m = make(rng, iter);
        expect_exactly_once(m, 1, rng);
        expect_exactly_once(m, 4, rng);
    }
}

}  // namespace

TEST(FillRule, JitteredGridsCoverEachSampleOnce) {
    expect_exactly_once_for_30(7, [](std::mt19937& rng, int iter) { return grid(rng, 2 + iter % 9); });
}

TEST(FillRule, FansCoverEachSampleOnce) {
    expect_exactly_once_for_30(11, [](std::mt19937& rng, int) { return polygon(rng, true); });
}

TEST(FillRule, RandomPolygonTriangulationsCoverEachSampleOnce) {
    expect_exactly_once_for_30(13, [](std::mt19937& rng, int) { return polygon(rng, false); });
}

TEST(FillRule, AxisAlignedEdgesOnSampleCenters) {
    // Edges exactly through pixel centers: the top-left rule decides. Two triangles of a
    // square from (10.5, 10.5) to (20.5, 20.5): samples on the top and left edges belong to
    // the square, those on the bottom and right edges do not. 10 x 10 samples in all.
    Mesh2D m;
    m.points = {{10.5f, 10.5f}, {20.5f, 10.5f}, {20.5f, 20.5f}, {10.5f, 20.5f}};
    m.indices = {0, 1, 2, 0, 2, 3};
    std::mt19937 rng(1);
    const std::vector<int> counts = coverage_counts(m, 1, rng);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int expected = (x >= 10 && x < 20 && y >= 10 && y < 20) ? 1 : 0;
            ASSERT_EQ(counts[size_t(y) * W + size_t(x)], expected) << x << "," << y;
        }
}

TEST(FillRule, ClippedGroundCoversEverySampleOnce) {
    // A jittered grid on the ground, seen from above at a steep angle: it fills the whole
    // picture, and the triangles under the camera cross the near plane and are clipped.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    for (int samples : {1, 4}) {
        Framebuffer fb(W, H, samples);
        Context ctx(fb);
        count_coverage(ctx);
        const glm::mat4 vp = glm::perspective(glm::radians(45.0f), float(W) / H, 0.1f, 100.0f) *
                             glm::lookAt(glm::vec3(0, 1, 0), glm::vec3(0, 0, -0.6f), glm::vec3(0, 1, 0));
        const int n = 40;
        std::vector<ClipVertexIn> v;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                glm::vec2 q{float(i), float(j)};
                if (i > 0 && i < n && j > 0 && j < n) q += glm::vec2(jitter(rng), jitter(rng));
                const glm::vec3 p(-10.0f + 20.0f * q.x / n, 0.0f, -10.0f + 20.0f * q.y / n);
                v.push_back({vp * glm::vec4(p, 1.0f), 0});
            }
        const std::vector<uint32_t> idx = grid_indices(n, [](uint32_t) { return true; });
        draw(ctx, ConstantColorShader{glm::vec4(1, 1, 1, 1.0f / 255.0f)}, v, idx);
        for (size_t i = 0; i < size_t(W) * H * size_t(samples); ++i)
            ASSERT_EQ(fb.color_data()[i].r, 1) << "sample " << i << " samples=" << samples;
    }
}
