// Lesson 7 (course/07-clipping): Cohen-Sutherland clips a segment to the same piece as the
// production pipeline's line clipper (Liang-Barsky, include/softraster/pipeline/clipping.h),
// and the lesson's Sutherland-Hodgman gives the same polygons as the pipeline's triangle
// clipper, on random segments and triangles, including corners behind the camera (w < 0).
#include <gtest/gtest.h>

#include <random>

#include "course/07-clipping/clip.h"
#include "softraster/pipeline/clipping.h"

using namespace course;

TEST(CourseClipping, CohenSutherlandKeepsWhatTheLineClipperKeeps) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
    const softraster::ClipPlanes frustum = softraster::ClipPlanes::frustum();
    int kept = 0, dropped = 0;
    for (int n = 0; n < 20000; ++n) {
        Segment2 s{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        // The same segment in clip space, w = 1: the window [-1, 1]^2 is the frustum's x, y.
        softraster::ClipVertex<0> p0{glm::vec4(s.a, 0.0f, 1.0f), {}}, p1{glm::vec4(s.b, 0.0f, 1.0f), {}};
        const bool ours = clip_cohen_sutherland(s, glm::vec2(-1.0f), glm::vec2(1.0f));
        const bool pipeline = softraster::clip_line(p0, p1, frustum);
        ASSERT_EQ(ours, pipeline) << n;
        if (!ours) {
            ++dropped;
            continue;
        }
        ++kept;
        // The same piece; the ends may come out in either order of computation, not of place.
        EXPECT_NEAR(s.a.x, p0.position.x, 1e-5f);
        EXPECT_NEAR(s.a.y, p0.position.y, 1e-5f);
        EXPECT_NEAR(s.b.x, p1.position.x, 1e-5f);
        EXPECT_NEAR(s.b.y, p1.position.y, 1e-5f);
    }
    EXPECT_GT(kept, 2000);
    EXPECT_GT(dropped, 2000);
}

TEST(CourseClipping, SutherlandHodgmanGivesThePipelinesPolygons) {
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f), w(-2.0f, 4.0f);
    const softraster::ClipPlanes frustum = softraster::ClipPlanes::frustum();
    int behind = 0, clipped = 0;
    for (int n = 0; n < 20000; ++n) {
        ClipCorner c[3];
        softraster::ClipVertex<3> v[3];
        for (int k = 0; k < 3; ++k) {
            c[k] = {{coord(rng), coord(rng), coord(rng), w(rng)}, {coord(rng), coord(rng), coord(rng)}};
            v[k] = {c[k].position, {c[k].color.r, c[k].color.g, c[k].color.b}};
            behind += c[k].position.w < 0.0f;
        }
        const std::vector<ClipCorner> ours = clip_to_frustum({c[0], c[1], c[2]});
        softraster::ClipPolygon<3> theirs;
        const int count = softraster::clip_triangle(v[0], v[1], v[2], frustum, 0x3f, theirs);
        ASSERT_EQ(int(ours.size()), count) << n;
        clipped += count > 3;
        for (int k = 0; k < count; ++k) {
            for (int i = 0; i < 4; ++i) ASSERT_EQ(ours[size_t(k)].position[i], theirs.v[size_t(k)].position[i]) << n;
            for (int i = 0; i < 3; ++i) ASSERT_NEAR(ours[size_t(k)].color[i], theirs.v[size_t(k)].var[size_t(i)], 1e-5f) << n;
        }
    }
    EXPECT_GT(behind, 1000);
    EXPECT_GT(clipped, 1000);
}
