// Lesson 9 (course/09-interpolation): perspective-correct interpolation gives the values the
// production pipeline's interpolation gives (include/softraster/pipeline/interpolation.h), and
// affine interpolation equals it under an orthographic camera (every w = 1) but not under a
// perspective one.
#include <gtest/gtest.h>

#include <random>

#include "course/03-triangles/fill.h"
#include "course/08-viewport/viewport.h"
#include "course/09-interpolation/interpolate.h"
#include "softraster/context.h"
#include "test_support.h"

using namespace course;

namespace {

constexpr int kSize = 64;

// Random clip-space triangles whose corners lie inside the view volume, at depths w in
// [w_lo, w_hi]; for each pixel center the pipeline shades, the lesson's value beside it.
// (The weights come from the corners' window positions before snapping, as the pipeline's
// attribute planes do: snapping decides coverage only, lesson 3.)
template <class Check>
void compare(std::mt19937& rng, float w_lo, float w_hi, Check check) {
    std::uniform_real_distribution<float> ndc(-0.95f, 0.95f), w(w_lo, w_hi), value(-10.0f, 10.0f);
    for (int n = 0; n < 200; ++n) {
        softraster::test::ClipVertexIn v[3];
        std::array<float, 3> a, ws;
        Point s[3];
        ScreenWeights weights;  // unsnapped: the pipeline builds its attribute planes from these
        for (int k = 0; k < 3; ++k) {
            ws[size_t(k)] = w(rng);
            v[k].clip = glm::vec4(ndc(rng), ndc(rng), ndc(rng), 1.0f) * ws[size_t(k)];
            v[k].value = a[size_t(k)] = value(rng);
            const ScreenPoint p = to_viewport(v[k].clip, {0, 0, float(kSize), float(kSize)});
            s[k] = {std::lround(p.x * kSub), std::lround(p.y * kSub)};
            weights.x[k] = p.x, weights.y[k] = p.y;
        }
        const double area = double(edge_function(s[0], s[1], s[2]));
        if (std::fabs(area) < 4.0 * kSub * kSub) continue;
        std::vector<float> captured(kSize * kSize, NAN);
        softraster::Framebuffer fb(kSize, kSize);
        softraster::Context ctx(fb);
        ctx.state.cull = softraster::CullMode::None;
        const uint32_t indices[] = {0, 1, 2};
        ctx.draw(softraster::Topology::Triangles, softraster::test::CaptureShader{&captured, kSize},
                 std::span<const softraster::test::ClipVertexIn>(v, 3), std::span<const uint32_t>(indices));
        ctx.finish();
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float got = captured[size_t(y * kSize + x)];
                if (std::isnan(got)) continue;
                check(got, weights.at(x + 0.5, y + 0.5), a, ws);
            }
    }
}

}  // namespace

TEST(CourseInterpolation, PerspectiveCorrectIsWhatThePipelineInterpolates) {
    std::mt19937 rng(13);
    size_t pixels = 0;
    double worst_affine = 0.0;
    compare(rng, 0.5f, 8.0f, [&](float got, const auto& l, const auto& a, const auto& w) {
        ASSERT_NEAR(interpolate_perspective(l, a, w), got, 1e-3f);  // (the pipeline works in float: 1e-4 of the values' range)
        worst_affine = std::max(worst_affine, double(std::fabs(interpolate_affine(l, a) - got)));
        ++pixels;
    });
    EXPECT_GT(pixels, 10000u);
    EXPECT_GT(worst_affine, 1.0);  // affine is visibly off under perspective
}

TEST(CourseInterpolation, AffineEqualsPerspectiveCorrectUnderAnOrthographicCamera) {
    std::mt19937 rng(14);
    size_t pixels = 0;
    compare(rng, 1.0f, 1.0f, [&](float got, const auto& l, const auto& a, const auto& w) {
        ASSERT_NEAR(interpolate_affine(l, a), interpolate_perspective(l, a, w), 1e-5f);
        ASSERT_NEAR(interpolate_affine(l, a), got, 1e-3f);
        ++pixels;
    });
    EXPECT_GT(pixels, 10000u);
}
