// Perspective-correct interpolation against the analytic answer: a tilted quad seen in
// perspective carries its world-space height as a varying; at every pixel center the
// interpolated value must equal the height where the eye ray through that center hits it.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/vertex_processing.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

TEST(Interpolation, PerspectiveCorrectMatchesRayCast) {
    constexpr int W = 160, H = 120;
    const float fov = glm::radians(60.0f), aspect = float(W) / H;
    const glm::mat4 proj = glm::perspective(fov, aspect, 0.5f, 50.0f);
    // Quad from near (z = -1) to far (z = -9) rising in y: strong perspective foreshortening.
    const glm::vec3 p[4] = {{-2, -1, -1}, {2, -1, -1}, {2, 3, -9}, {-2, 3, -9}};
    std::vector<ClipVertexIn> v;
    for (const glm::vec3& q : p) v.push_back({proj * glm::vec4(q, 1.0f), q.y});
    std::vector<float> values(size_t(W) * H, NAN);
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    ctx.state.cull = CullMode::None;
    draw(ctx, CaptureShader{&values, W}, v, {0, 1, 2, 0, 2, 3});

    // Plane of the quad: points q with n . q = n . p0.
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[3] - p[0]));
    const float tan_half = std::tan(fov / 2);
    int checked = 0;
    float worst_affine_error = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float got = values[size_t(y) * W + size_t(x)];
            if (std::isnan(got)) continue;
            const glm::vec3 dir((2.0f * (x + 0.5f) / W - 1.0f) * tan_half * aspect, (1.0f - 2.0f * (y + 0.5f) / H) * tan_half, -1.0f);
            const float t = glm::dot(n, p[0]) / glm::dot(n, dir);
            const float expected = (t * dir).y;
            ASSERT_NEAR(got, expected, 2e-4f * (1.0f + std::fabs(expected))) << x << "," << y;
            // What screen-space (affine) interpolation would give along this column: linear in y.
            worst_affine_error = std::max(worst_affine_error, std::fabs(expected - (-1.0f + 4.0f * (1.0f - (y + 0.5f) / H))));
            ++checked;
        }
    EXPECT_GT(checked, 2000);
    EXPECT_GT(worst_affine_error, 0.5f);  // the test can tell perspective from affine interpolation
}

TEST(Interpolation, DepthIsAffineInWindowSpace) {
    constexpr int W = 64, H = 64;
    std::vector<ClipVertexIn> v = {{window_to_clip(0, 0, W, H, 0.1f), 0},
                                   {window_to_clip(128, 0, W, H, 0.9f), 0},
                                   {window_to_clip(0, 128, W, H, 0.5f), 0}};
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    draw(ctx, ConstantColorShader{}, v, {0, 2, 1});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float expected = 0.1f + 0.8f * (x + 0.5f) / 128 + 0.4f * (y + 0.5f) / 128;
            EXPECT_NEAR(fb.depth_data()[fb.sample_index(x, y)], expected, 1e-6f);
        }
}

// A varying with the same value at every corner is that value at every pixel, exactly, in
// perspective too, when the draw's planes look for constant varyings: setup keeps the value
// instead of dividing a/w by 1/w (setup_planes). Without looking, the division rounds.
TEST(Interpolation, ConstantVaryingsAreExact) {
    constexpr int W = 97, H = 61;
    const glm::mat4 proj = glm::perspective(glm::radians(70.0f), float(W) / H, 0.3f, 40.0f);
    const float value = 0.7123f;  // (0.7123 * 1/w) / (1/w) rounds away from it at some pixels
    const glm::vec3 p[3] = {{-3, -1, -1}, {3, -1, -1}, {3, 4, -30}};
    std::array<ShadedVertex<1>, 3> v;
    for (size_t k = 0; k < 3; ++k)
        ASSERT_TRUE(finish_vertex(ClipVertex<1>{proj * glm::vec4(p[k], 1.0f), {value}}, Viewport{W, H}, v[k]));
    const Rect rect{0, 0, W, H};
    TriangleSetup<1> exact, divided, unasked;
    ASSERT_TRUE(setup_coverage<1>(v[0], v[1], v[2], FrontFace::CCW, rect, exact));
    ASSERT_TRUE(setup_coverage<1>(v[0], v[1], v[2], FrontFace::CCW, rect, divided));
    ASSERT_TRUE(setup_coverage<1>(v[0], v[1], v[2], FrontFace::CCW, rect, unasked));
    exact.options.find_constant = true;  // (a blended draw's)
    setup_planes</*Flat=*/0, /*Constant=*/true>(exact);
    setup_planes</*Flat=*/0, /*Constant=*/false>(divided);
    setup_planes</*Flat=*/0, /*Constant=*/true>(unasked);  // compiled to look, but an opaque draw does not ask
    EXPECT_TRUE(exact.constant_varyings);
    EXPECT_FALSE(divided.constant_varyings);
    EXPECT_FALSE(unasked.constant_varyings);
    int rounded = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float i = float(x), j = float(y);
            ASSERT_EQ((interpolate_perspective<0, true>(exact, i, j)[0]), value) << x << "," << y;
            if (interpolate_perspective<0, false>(divided, i, j)[0] != value) ++rounded;
        }
    EXPECT_GT(rounded, 0);  // the test can tell the two apart
}

namespace {
// Captures, per pixel, a varying (u, v) and the derivatives interpolation fills in.
struct UvDerivativeVaryings {
    glm::vec2 uv;
    glm::vec4 d;  // du/dx, dv/dx, du/dy, dv/dy
};
struct DerivativeCaptureShader {
    using Vertex = ClipVertexIn;
    using Varyings = UvDerivativeVaryings;
    static constexpr int kDerivativeOf = 0;
    static constexpr int kDerivativeAt = 2;
    static constexpr uint64_t kFlat = varying_bits(offsetof(UvDerivativeVaryings, d), sizeof(glm::vec4));
    std::vector<Varyings>* out;
    int width;
    glm::vec4 vertex(const Vertex& in, Varyings& v) const {
        v.uv = glm::vec2(in.value, in.value * in.value);
        v.d = glm::vec4(0.0f);
        return in.clip;
    }
    bool fragment(const Varyings& v, const FragCoord& f, glm::vec4& c) const {
        (*out)[size_t(int(f.y) * width + int(f.x))] = v;
        c = glm::vec4(1.0f);
        return true;
    }
};
}  // namespace

// Derivatives are GL's coarse ones, per 2x2 quad of pixels (even x and y at its top left):
// the differences of the perspective-correct values across the quad, the same for its four
// pixels. Checked where the whole quad is covered, against the values the pixels captured.
TEST(Interpolation, DerivativesAreDifferencesAcrossTheQuad) {
    constexpr int W = 96, H = 64;
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(W) / H, 0.5f, 50.0f);
    const glm::vec3 p[4] = {{-2, -1, -1}, {2, -1, -1}, {2, 3, -9}, {-2, 3, -9}};
    const float value[4] = {0.1f, 0.9f, 2.5f, -1.3f};
    std::vector<ClipVertexIn> v;
    for (int k = 0; k < 4; ++k) v.push_back({proj * glm::vec4(p[k], 1.0f), value[k]});
    std::vector<UvDerivativeVaryings> got(size_t(W) * H, UvDerivativeVaryings{glm::vec2(NAN), glm::vec4(NAN)});
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0));
    ctx.state.cull = CullMode::None;
    draw(ctx, DerivativeCaptureShader{&got, W}, v, {0, 1, 2});  // (one triangle: every quad's pixels share its planes)
    auto at = [&](int x, int y) { return got[size_t(y) * W + size_t(x)]; };
    int quads = 0;
    for (int y = 0; y < H; y += 2)
        for (int x = 0; x < W; x += 2) {
            const UvDerivativeVaryings tl = at(x, y), tr = at(x + 1, y), bl = at(x, y + 1), br = at(x + 1, y + 1);
            if (std::isnan(tl.uv.x) || std::isnan(tr.uv.x) || std::isnan(bl.uv.x) || std::isnan(br.uv.x)) continue;
            const glm::vec4 expected(tr.uv.x - tl.uv.x, tr.uv.y - tl.uv.y, bl.uv.x - tl.uv.x, bl.uv.y - tl.uv.y);
            for (const UvDerivativeVaryings& px : {tl, tr, bl, br})
                for (int c = 0; c < 4; ++c) ASSERT_EQ(px.d[c], expected[c]) << x << "," << y << " component " << c;
            ++quads;
        }
    EXPECT_GT(quads, 150);
}
