// Lesson 8 (course/08-viewport): the lesson's divide and viewport transform put a clip-space
// point where the pipeline's vertex processing puts it (include/softraster/pipeline/viewport.h),
// and to_ndc undoes it.
#include <gtest/gtest.h>

#include <random>

#include "course/08-viewport/viewport.h"
#include "softraster/pipeline/viewport.h"

using namespace course;

TEST(CourseViewport, ThePipelinesWindowCoordinatesAndBack) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f), w(0.1f, 5.0f);
    for (int n = 0; n < 10000; ++n) {
        const glm::vec4 clip(coord(rng), coord(rng), coord(rng), w(rng));
        const ScreenPoint ours = to_viewport(clip, {0, 0, 640, 480});
        softraster::WindowPosition theirs;
        ASSERT_TRUE(softraster::to_window(clip, softraster::Viewport{640, 480}, theirs));
        EXPECT_NEAR(ours.x, theirs.x, 1e-3f);
        EXPECT_NEAR(ours.y, theirs.y, 1e-3f);
        EXPECT_NEAR(ours.depth, theirs.z, 1e-5f);
        const ViewportRect quarter{320, 240, 320, 240};
        const ScreenPoint p = to_viewport(clip, quarter);
        const glm::vec2 ndc = to_ndc(p.x, p.y, quarter);
        EXPECT_NEAR(ndc.x, clip.x / clip.w, 1e-4f);
        EXPECT_NEAR(ndc.y, clip.y / clip.w, 1e-4f);
    }
}
