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

struct Counts {
    int inside = 0, outside = 0, unmapped = 0, nonfinite = 0;
};

// Processes `in` on the generic path or the AVX2 one and checks every vertex against the
// one-vertex helpers.
Counts expect_same_as_one_at_a_time(const std::vector<ClipVertexIn>& in, const Viewport& vp, bool wide) {
    const ClipPlanes planes = ClipPlanes::for_viewport(vp.width, vp.height);
    std::vector<ShadedVertex<1>> out(in.size());
    std::vector<ClipInfo> clip(in.size());
    if (wide) {
        process_vertices<true>(ConstantColorShader{}, std::span<const ClipVertexIn>(in), 0, in.size(), planes, vp, std::span<ShadedVertex<1>>(out),
                               std::span<ClipInfo>(clip));
    } else {
        process_vertices(ConstantColorShader{}, std::span<const ClipVertexIn>(in), 0, in.size(), planes, vp, std::span<ShadedVertex<1>>(out),
                         std::span<ClipInfo>(clip));
    }
    Counts n;
    for (size_t i = 0; i < in.size(); ++i) {
        SCOPED_TRACE(testing::Message() << "vertex " << i << (wide ? ", AVX2 path" : ", generic path"));
        const glm::vec4 p = in[i].clip;
        const ShadedVertex<1>& o = out[i];
        const ClipInfo& c = clip[i];
        EXPECT_EQ(std::bit_cast<glm::uvec4>(c.position), std::bit_cast<glm::uvec4>(p));
        EXPECT_EQ(o.var[0], float(i));
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
        if (!finite) {
            EXPECT_FALSE(c.finite);
            ++n.nonfinite;
            continue;
        }
        EXPECT_EQ(c.outcode, planes.outcode(p));
        if (c.outcode != 0) {
            EXPECT_TRUE(c.finite);
            ++n.outside;
            continue;
        }
        WindowPosition wp;
        const bool mapped = to_window(p, vp, wp);
        EXPECT_EQ(c.finite, mapped);
        if (!mapped) {
            ++n.unmapped;
            continue;
        }
        EXPECT_EQ(std::bit_cast<uint32_t>(o.window.x), std::bit_cast<uint32_t>(wp.x));
        EXPECT_EQ(std::bit_cast<uint32_t>(o.window.y), std::bit_cast<uint32_t>(wp.y));
        EXPECT_EQ(std::bit_cast<uint32_t>(o.window.z), std::bit_cast<uint32_t>(wp.z));
        EXPECT_EQ(std::bit_cast<uint32_t>(o.window.inv_w), std::bit_cast<uint32_t>(wp.inv_w));
        EXPECT_EQ(o.X, snap_to_subpixel(wp.x));
        EXPECT_EQ(o.Y, snap_to_subpixel(wp.y));
        EXPECT_EQ(c.X, o.X);  // (binning reads them from the clip part)
        EXPECT_EQ(c.Y, o.Y);
        ++n.inside;
    }
    return n;
}

// Both CPU paths (the AVX2 one where it runs).
std::vector<bool> paths() {
    if (simd::wide_path_runs()) return {false, true};
    return {false};
}

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
    for (bool wide : paths()) {
        const Counts n = expect_same_as_one_at_a_time(in, Viewport{317, 211}, wide);
        EXPECT_GT(n.inside, 300);
        EXPECT_GT(n.outside, 200);
        EXPECT_GT(n.nonfinite, 20);
        EXPECT_EQ(n.unmapped, 2);
    }
}

// Window positions exactly halfway between two 1/256 steps snap to the even one on both
// paths, as lrint does: in a 256 x 256 viewport, x = (2n + 1) / 2^16 - 1 (exact in float)
// maps to 256 x_window = n + 1/2.
TEST(VertexProcessing, SnappingRoundsHalfwayToEven) {
    std::vector<ClipVertexIn> in(96);
    for (size_t i = 0; i < in.size(); ++i) {
        const float x = float(2 * (i * 611 % 65536) + 1) / 65536.0f - 1.0f, y = float(2 * i + 1) / 65536.0f - 1.0f;
        in[i] = {glm::vec4(x, -y, 0.0f, 1.0f), float(i)};
    }
    for (bool wide : paths()) EXPECT_EQ(expect_same_as_one_at_a_time(in, Viewport{256, 256}, wide).inside, 96);
}

}  // namespace
