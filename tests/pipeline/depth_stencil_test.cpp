// The stencil test and its operations (depth_stencil.h), sample by sample, in GL's order.
#include <gtest/gtest.h>

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
