// Depth precision: with an extreme near/far ratio (near 1e-4, far 1e4) window depths far
// from the camera differ from 1 in their last few bits, so every rounding in depth
// interpolation shows. The interpolated depth must be the exact plane through the three
// window-space vertices, rounded once to float (within a fraction of a unit in the last
// place), and where two planes cross the nearer one must win wherever they differ by
// more than that: no blocks along the crossing.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 320, H = 240;

// A far, tilted quad in clip space (float, as a vertex shader makes it), seen through a
// perspective camera with near 1e-4 and far 1e4.
std::vector<ClipVertexIn> far_quad(float tilt) {
    const glm::dmat4 proj = glm::perspective(glm::radians(50.0), double(W) / H, 1e-4, 1e4);
    std::vector<ClipVertexIn> v;
    for (auto [x, y] : {std::pair{-200.0, -150.0}, {200.0, -150.0}, {200.0, 150.0}, {-200.0, 150.0}}) {
        const glm::dvec4 eye(x, y, -100.0 + tilt * x, 1.0);
        v.push_back({glm::vec4(proj * eye), 0});
    }
    return v;
}

// Window depth of the plane through the quad's window-space corners (as the pipeline maps
// them, in float), at the center of pixel (x, y), in double.
struct ExactPlane {
    double a, b, c;  // z = a x + b y + c
    explicit ExactPlane(const std::vector<ClipVertexIn>& v) {
        std::array<glm::dvec3, 3> p;
        for (int i = 0; i < 3; ++i) {
            WindowPosition w;
            EXPECT_TRUE(to_window(v[size_t(i)].clip, Viewport{W, H}, w));
            p[size_t(i)] = glm::dvec3(w.x, w.y, w.z);
        }
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        a = -n.x / n.z, b = -n.y / n.z, c = p[0].z - a * p[0].x - b * p[0].y;
    }
    double at(int x, int y) const { return a * (x + 0.5) + b * (y + 0.5) + c; }
};

std::vector<float> depth_of(const std::vector<std::vector<ClipVertexIn>>& quads, std::vector<Rgba8>* color = nullptr) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1), 1.0f);
    ctx.state.cull = CullMode::None;
    for (size_t q = 0; q < quads.size(); ++q)
        draw(ctx, ConstantColorShader{glm::vec4(q == 0, q == 1, 0, 1)}, quads[q], {0, 1, 2, 0, 2, 3});
    if (color) color->assign(fb.color_data(), fb.color_data() + W * H);
    return std::vector<float>(fb.depth_data(), fb.depth_data() + W * H);
}

// Units in the last place of float near z.
double ulp(double z) { return double(std::nextafter(float(z), 2.0f) - float(z)); }

}  // namespace

TEST(DepthPrecision, InterpolatedDepthIsTheExactPlaneRoundedOnce) {
    for (float tilt : {0.0f, 0.05f, -0.2f}) {
        const auto quad = far_quad(tilt);
        const ExactPlane plane(quad);
        const std::vector<float> depth = depth_of({quad});
        double worst = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double exact = plane.at(x, y);
                ASSERT_LT(exact, 1.0);
                worst = std::max(worst, std::fabs(double(depth[size_t(y * W + x)]) - exact) / ulp(exact));
            }
        EXPECT_LE(worst, 0.6) << "tilt " << tilt << ": worst error " << worst << " units in the last place";
    }
}

TEST(DepthPrecision, CrossingPlanesMeetAlongTheExactLine) {
    const auto a = far_quad(0.08f), b = far_quad(-0.08f);
    const ExactPlane pa(a), pb(b);
    std::vector<Rgba8> color;
    depth_of({a, b}, &color);
    int wrong = 0, decided = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double za = pa.at(x, y), zb = pb.at(x, y);
            if (std::fabs(za - zb) <= 1.0 * ulp(za)) continue;  // equal as floats, or nearly: either may win
            ++decided;
            const bool a_wins = color[size_t(y * W + x)].r == 255;
            wrong += a_wins != (za < zb);
        }
    EXPECT_GT(decided, W * H / 3);
    EXPECT_EQ(wrong, 0);
}
