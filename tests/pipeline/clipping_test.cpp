// Clipping: random triangles against the frustum. Every output vertex lies inside the clip
// volume, and its varyings agree with the input (varyings here are an affine function of
// the clip position, which clipping must preserve exactly up to rounding).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/simd.h"

using namespace softraster;

namespace {

constexpr int N = 2;
const glm::vec4 kCoefA(0.3f, -1.2f, 0.7f, 2.0f), kCoefB(-0.5f, 0.25f, 1.5f, -0.75f);

ClipVertex<N> make_vertex(const glm::vec4& p) {
    return {p, {glm::dot(kCoefA, p), glm::dot(kCoefB, p)}};
}

}  // namespace

// The outcodes' distances are the planes' dot products as the clipper's glm::dot sums them,
// bit for bit (but the sign of a zero), one point at a time and eight at once: for points
// anywhere, of every magnitude, and exactly on each plane and one step to either side.
TEST(ClipPlanes, DistancesAreTheDotProducts) {
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_int_distribution<int> scale(-30, 30);
    for (const ClipPlanes& planes : {ClipPlanes::frustum(), ClipPlanes::for_viewport(1920, 1080), ClipPlanes::for_viewport(37, 5)}) {
        std::vector<glm::vec4> points;
        for (int k = 0; k < 4000; ++k) {
            glm::vec4 p(u(rng), u(rng), u(rng), u(rng));
            for (int c = 0; c < 4; ++c) p[c] = std::ldexp(p[c], scale(rng));
            points.push_back(p);
            // on plane i: its one free coordinate set so that the plane's sum is 0, then a step
            // either way
            const size_t i = size_t(k) % ClipPlanes::kCount;
            const glm::vec4& q = planes.planes()[i];
            const int axis = q.x != 0 ? 0 : q.y != 0 ? 1 : 2;
            glm::vec4 on = p;
            on[axis] = -q[axis] * (q.w * p.w);
            for (float toward : {-INFINITY, 0.0f, INFINITY}) {
                glm::vec4 v = on;
                if (toward != 0.0f) v[axis] = std::nextafter(v[axis], toward);
                points.push_back(v);
            }
        }
        for (size_t k = 0; k + simd::kLanes <= points.size(); k += simd::kLanes) {
            simd::f8 x, y, z, w;
            for (int l = 0; l < simd::kLanes; ++l) {
                const glm::vec4& p = points[k + size_t(l)];
                x[l] = p.x, y[l] = p.y, z[l] = p.z, w[l] = p.w;
            }
            const std::array<simd::f8, ClipPlanes::kCount> lanes = planes.distances(x, y, z, w);
            for (int l = 0; l < simd::kLanes; ++l) {
                const glm::vec4& p = points[k + size_t(l)];
                const std::array<float, ClipPlanes::kCount> d = planes.distances(p.x, p.y, p.z, p.w);
                unsigned code = 0;
                for (size_t i = 0; i < size_t(ClipPlanes::kCount); ++i) {
                    const float dot = glm::dot(planes.planes()[i], p);
                    ASSERT_EQ(d[i], dot) << "plane " << i << " at " << p.x << " " << p.y << " " << p.z << " " << p.w;
                    ASSERT_EQ(lanes[i][l], dot) << "plane " << i << ", lane " << l;
                    code |= unsigned(dot < 0.0f) << i;
                }
                ASSERT_EQ(planes.outcode(p), code);
            }
        }
    }
}

TEST(Clipping, RandomTrianglesStayInsideAndKeepVaryings) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f), wdist(-1.0f, 3.0f);
    const ClipPlanes planes = ClipPlanes::frustum();
    int clipped = 0, rejected = 0;
    for (int iter = 0; iter < 20000; ++iter) {
        ClipVertex<N> v[3];
        for (auto& x : v) x = make_vertex(glm::vec4(coord(rng), coord(rng), coord(rng), wdist(rng)));
        unsigned mask = 0;
        for (auto& x : v) mask |= planes.outcode(x.position);
        ClipPolygon<N> poly;
        const int n = clip_triangle(v[0], v[1], v[2], planes, mask, poly);
        if (n == 0) {
            ++rejected;
            continue;
        }
        if (mask) ++clipped;
        ASSERT_GE(n, 3);
        ASSERT_LE(n, ClipPolygon<N>::kMaxVertices);
        for (int i = 0; i < n; ++i) {
            const glm::vec4 p = poly.v[size_t(i)].position;
            const float tol = 1e-5f * (1.0f + std::fabs(p.w));
            EXPECT_GE(p.w + tol, std::fabs(p.x));
            EXPECT_GE(p.w + tol, std::fabs(p.y));
            EXPECT_GE(p.w + tol, std::fabs(p.z));
            EXPECT_NEAR(poly.v[size_t(i)].var[0], glm::dot(kCoefA, p), 1e-4f * (1 + glm::length(p)));
            EXPECT_NEAR(poly.v[size_t(i)].var[1], glm::dot(kCoefB, p), 1e-4f * (1 + glm::length(p)));
        }
    }
    EXPECT_GT(clipped, 1000);
    EXPECT_GT(rejected, 1000);
}

TEST(Clipping, TriangleInsideIsUnchanged) {
    // Clipped against any set of the six planes (as if they were crossed), a triangle inside
    // them all comes back as it was: the same three vertices, bit for bit, in order.
    const ClipPlanes planes = ClipPlanes::frustum();
    const ClipVertex<N> in[3] = {make_vertex({-0.3f, -0.2f, 0.1f, 1}), make_vertex({0.5f, 0.1f, -0.4f, 1.5f}),
                                 make_vertex({0.1f, 0.6f, 0.3f, 0.9f})};
    for (const auto& v : in) ASSERT_EQ(planes.outcode(v.position), 0u);
    for (unsigned mask = 1; mask < (1u << ClipPlanes::kCount); ++mask) {  // every set of planes
        ClipPolygon<N> poly;
        ASSERT_EQ(clip_triangle(in[0], in[1], in[2], planes, mask, poly), 3) << "planes " << mask;
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(poly.v[size_t(i)].position, in[i].position) << "planes " << mask << " vertex " << i;
            EXPECT_EQ(poly.v[size_t(i)].var, in[i].var) << "planes " << mask << " vertex " << i;
        }
    }
}

TEST(Clipping, TriangleBehindEyeIsCutAtNearPlane) {
    // One vertex behind the eye (w < 0): the result must have w > 0 everywhere.
    const ClipPlanes planes = ClipPlanes::frustum();
    ClipVertex<N> a = make_vertex({-0.5f, 0, 0.5f, 1}), b = make_vertex({0.5f, 0, 0.5f, 1}),
                  c = make_vertex({0, 0.5f, -3.0f, -2.0f});
    ClipPolygon<N> poly;
    const int n = clip_triangle(a, b, c, planes, planes.outcode(c.position), poly);
    ASSERT_GE(n, 3);
    for (int i = 0; i < n; ++i) {
        EXPECT_GT(poly.v[size_t(i)].position.w, 0.0f);
        EXPECT_GE(poly.v[size_t(i)].position.z + poly.v[size_t(i)].position.w, -1e-6f);
    }
}

TEST(Clipping, SharedEdgeGivesIdenticalVertices) {
    // Two triangles share edge (a, b) that crosses the near plane, in opposite directions.
    const ClipPlanes planes = ClipPlanes::frustum();
    ClipVertex<N> a = make_vertex({-0.3f, 0.1f, 0.5f, 1}), b = make_vertex({0.2f, -0.4f, -2.7f, -1.3f});
    ClipVertex<N> c = make_vertex({0.6f, 0.6f, 0.4f, 1}), d = make_vertex({-0.7f, -0.6f, 0.3f, 1});
    ClipPolygon<N> p1, p2;
    const int n1 = clip_triangle(a, b, c, planes, 1u, p1);
    const int n2 = clip_triangle(b, a, d, planes, 1u, p2);
    ASSERT_GT(n1, 0);
    ASSERT_GT(n2, 0);
    // The vertex on the near plane along edge (a, b) must appear bit-identically in both.
    int matches = 0;
    for (int i = 0; i < n1; ++i)
        for (int j = 0; j < n2; ++j)
            if (p1.v[size_t(i)].position == p2.v[size_t(j)].position && p1.v[size_t(i)].position != a.position) ++matches;
    EXPECT_EQ(matches, 1);
}

TEST(Clipping, LineIsTrimmedToFrustum) {
    const ClipPlanes planes = ClipPlanes::frustum();
    ClipVertex<N> p0 = make_vertex({-3, 0, 0, 1}), p1 = make_vertex({3, 0, 0, 1});
    ASSERT_TRUE(clip_line(p0, p1, planes));
    EXPECT_NEAR(p0.position.x, -1.0f, 1e-6f);
    EXPECT_NEAR(p1.position.x, 1.0f, 1e-6f);
    EXPECT_NEAR(p0.var[0], glm::dot(kCoefA, p0.position), 1e-5f);
    ClipVertex<N> q0 = make_vertex({2, 0, 0, 1}), q1 = make_vertex({3, 1, 0, 1});
    EXPECT_FALSE(clip_line(q0, q1, planes));
}
