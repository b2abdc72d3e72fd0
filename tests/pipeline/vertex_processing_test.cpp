// Vertex processing (pipeline/vertex_processing.h): eight vertices at a time give the same
// post-transform vertices as the one-vertex helpers (ClipPlanes::outcode, to_window,
// snap_to_subpixel), bit for bit, for vertices inside, outside every plane, behind the eye,
// on w = 0, and with infinite or NaN coordinates; and a buffer whose length is not a
// multiple of eight has its last vertices done too.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "softraster/pipeline/vertex_processing.h"
#include "test_support.h"

using namespace softraster;
using test::ClipVertexIn;
using test::ConstantColorShader;

namespace {

TEST(VertexProcessing, EightAtATimeSameAsOneAtATime) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1, 1);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float specials[] = {0.0f, -0.0f, inf, -inf, nan, 1e30f, -1e-30f};
    std::vector<ClipVertexIn> in(1003);  // not a multiple of eight
    for (size_t i = 0; i < in.size(); ++i) {
        const float w = i % 5 == 0 ? 4 * u(rng) : 0.2f + std::abs(u(rng));  // some behind the eye
        glm::vec4 p(u(rng) * w * (i % 3 == 0 ? 40.0f : 1.2f), u(rng) * w * 1.2f, u(rng) * w * 1.2f, w);
        if (i % 17 == 0) p[int(i / 17 % 4)] = specials[i / 17 % 7];
        in[i] = {p, float(i)};
    }
    in[1].clip = glm::vec4(0.0f);  // inside every plane (on all of them), but w = 0: not mappable
    in[2].clip = glm::vec4(0.0f, 0.0f, 0.0f, -0.0f);
    const Viewport vp{317, 211};
    const ClipPlanes planes = ClipPlanes::for_viewport(vp.width, vp.height);
    std::vector<ShadedVertex<1>> out(in.size());
    std::vector<ClipInfo> clip(in.size());
    process_vertices(ConstantColorShader{}, std::span<const ClipVertexIn>(in), 0, in.size(), planes, vp, std::span<ShadedVertex<1>>(out),
                     std::span<ClipInfo>(clip));

    int inside = 0, outside = 0, unmapped = 0, nonfinite = 0;
    for (size_t i = 0; i < in.size(); ++i) {
        const glm::vec4 p = in[i].clip;
        const ShadedVertex<1>& o = out[i];
        const ClipInfo& c = clip[i];
        ASSERT_EQ(std::bit_cast<glm::uvec4>(c.position), std::bit_cast<glm::uvec4>(p)) << i;
        ASSERT_EQ(o.var[0], float(i));
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        if (!finite) {
            ASSERT_FALSE(c.finite) << i;
            ++nonfinite;
            continue;
        }
        ASSERT_EQ(c.outcode, planes.outcode(p)) << i;
        if (c.outcode != 0) {
            ASSERT_TRUE(c.finite) << i;
            ++outside;
            continue;
        }
        WindowPosition wp;
        const bool mapped = to_window(p, vp, wp);
        ASSERT_EQ(c.finite, mapped) << i;
        if (!mapped) {
            ++unmapped;
            continue;
        }
        ASSERT_EQ(std::bit_cast<uint32_t>(o.window.x), std::bit_cast<uint32_t>(wp.x)) << i;
        ASSERT_EQ(std::bit_cast<uint32_t>(o.window.y), std::bit_cast<uint32_t>(wp.y)) << i;
        ASSERT_EQ(std::bit_cast<uint32_t>(o.window.z), std::bit_cast<uint32_t>(wp.z)) << i;
        ASSERT_EQ(std::bit_cast<uint32_t>(o.window.inv_w), std::bit_cast<uint32_t>(wp.inv_w)) << i;
        ASSERT_EQ(o.X, snap_to_subpixel(wp.x)) << i;
        ASSERT_EQ(o.Y, snap_to_subpixel(wp.y)) << i;
        ASSERT_EQ(c.X, o.X) << i;  // (binning reads them from the clip part)
        ASSERT_EQ(c.Y, o.Y) << i;
        ++inside;
    }
    EXPECT_GT(inside, 300);
    EXPECT_GT(outside, 200);
    EXPECT_GT(nonfinite, 20);
    EXPECT_EQ(unmapped, 2);
}

}  // namespace
