// The stencil test and its operations (depth_stencil.h), sample by sample, in GL's order.
#include <gtest/gtest.h>

#include <random>

#include "softraster/pipeline/depth_stencil.h"

using namespace softraster;

TEST(Stencil, EveryOperation) {
    const uint8_t ref = 0x5a;
    struct Case {
        StencilOp op;
        uint8_t from, to;
    } cases[] = {{StencilOp::Keep, 7, 7},        {StencilOp::Zero, 7, 0},          {StencilOp::Replace, 7, ref},
                 {StencilOp::Incr, 7, 8},        {StencilOp::Incr, 255, 255},     {StencilOp::IncrWrap, 255, 0},
                 {StencilOp::Decr, 7, 6},        {StencilOp::Decr, 0, 0},         {StencilOp::DecrWrap, 0, 255},
                 {StencilOp::Invert, 0x0f, 0xf0}};
    for (const Case& c : cases) EXPECT_EQ(stencil_op_result(c.op, c.from, ref), c.to) << int(c.op) << " from " << int(c.from);
    StencilFace f;
    f.ref = 0xff;
    f.write_mask = 0x3c;  // only these bits change
    uint8_t v = 0x81;
    apply_stencil_op(f, StencilOp::Replace, v);
    EXPECT_EQ(v, 0xbd);  // 0x81 & ~0x3c | 0xff & 0x3c
}

TEST(Stencil, FailDepthFailPassPerFaceAndSample) {
    RenderState st;
    st.stencil_test = true;
    st.stencil_front = {CompareFunc::Equal, 1, 0xff, 0xff, StencilOp::Zero, StencilOp::Incr, StencilOp::Replace};
    st.stencil_back = {CompareFunc::Always, 9, 0xff, 0xff, StencilOp::Keep, StencilOp::Invert, StencilOp::Decr};
    const DepthStencilTest test(st);
    // sample 0: stencil fails; 1: stencil passes, depth fails; 2: both pass; 3: not covered
    float depth[4] = {0.5f, 0.1f, 0.9f, 0.5f};
    uint8_t stencil[4] = {3, 1, 1, 1};
    const float z[4] = {0.2f, 0.2f, 0.2f, 0.2f};
    EXPECT_EQ(test.test_and_write(depth, stencil, 4, 0b0111, z, true), 0b0100u);
    EXPECT_EQ(stencil[0], 0);      // fail: zero
    EXPECT_EQ(stencil[1], 2);      // depth fail: incr
    EXPECT_EQ(stencil[2], 1);      // pass: replace with 1
    EXPECT_EQ(stencil[3], 1);      // untouched
    EXPECT_EQ(depth[2], 0.2f);     // written
    EXPECT_EQ(depth[1], 0.1f);
    // the back face's state for a back-facing fragment
    uint8_t back[1] = {0x0f};
    float d[1] = {0.1f};
    EXPECT_EQ(test.test_and_write(d, back, 1, 1, z, false), 0u);
    EXPECT_EQ(back[0], 0xf0);  // depth fail: invert
}

TEST(Stencil, CompareUsesTheReadMask) {
    RenderState st;
    st.stencil_test = true;
    st.depth_test = false;
    st.stencil_front = st.stencil_back = {CompareFunc::Less, 0x12, 0x0f, 0xff, StencilOp::Keep, StencilOp::Keep, StencilOp::Keep};
    const DepthStencilTest test(st);
    float depth[1] = {0};
    const float z[1] = {1};
    uint8_t s[1] = {0xf3};  // (0x12 & 0xf) = 2 < (0xf3 & 0xf) = 3: passes; the high bits do not count
    EXPECT_EQ(test.test_and_write(depth, s, 1, 1, z, true), 1u);
    s[0] = 0x02;
    EXPECT_EQ(test.test_and_write(depth, s, 1, 1, z, true), 0u);
}

// The fast back end's eight-lane test (test_group) against the sample-by-sample one, for
// random functions, operations, masks and faces, and for a group cut by the row's end.
TEST(Stencil, EightLanesEqualOneAtATime) {
    std::mt19937 rng(7);
    auto pick = [&](int n) { return int(rng() % unsigned(n)); };
    for (int round = 0; round < 2000; ++round) {
        RenderState st;
        st.stencil_test = true;
        st.depth_test = pick(4) != 0;
        st.depth_write = pick(2) != 0;
        st.depth_func = CompareFunc(pick(8));
        for (StencilFace* f : {&st.stencil_front, &st.stencil_back}) {
            *f = {CompareFunc(pick(8)), uint8_t(pick(4) == 0 ? 255 : pick(4)), uint8_t(pick(2) ? 0xff : rng()),
                  uint8_t(pick(2) ? 0xff : rng()), StencilOp(pick(8)), StencilOp(pick(8)), StencilOp(pick(8))};
        }
        const DepthStencilTest test(st);
        const bool front = pick(2) != 0;
        const int width = pick(3) == 0 ? 3 + pick(5) : 8;  // fewer than eight pixels left in the row
        float depth[8], depth_one[8], z_lanes[8];
        uint8_t stencil[8], stencil_one[8];
        simd::i8 covered{};
        simd::f8 z{};
        for (int l = 0; l < 8; ++l) {
            depth[l] = depth_one[l] = float(pick(4)) * 0.25f;
            stencil[l] = stencil_one[l] = uint8_t(pick(3) == 0 ? 255 : pick(4));  // around 0, 255 and small refs
            z[l] = z_lanes[l] = float(pick(4)) * 0.25f;
            covered[l] = l < width && pick(4) != 0 ? -1 : 0;
        }
        const unsigned pass = simd::bits(test.test_group(depth, stencil, 0, width, z, covered, front));
        for (int l = 0; l < width; ++l) {
            const unsigned one = test.test_and_write(depth_one + l, stencil_one + l, 1, covered[l] ? 1u : 0u, z_lanes + l, front);
            EXPECT_EQ((pass >> l) & 1u, one) << "round " << round << " lane " << l;
            EXPECT_EQ(stencil[l], stencil_one[l]) << "round " << round << " lane " << l;
            EXPECT_EQ(depth[l], depth_one[l]) << "round " << round << " lane " << l;
        }
        for (int l = width; l < 8; ++l) EXPECT_EQ(stencil[l], stencil_one[l]) << "past the row's end, round " << round << " lane " << l;
        if (HasFailure()) return;
    }
}
