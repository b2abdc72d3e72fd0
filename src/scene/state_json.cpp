// The per-fragment state keys of scene files (docs/scene-format.md: an object's "depth" and
// "stencil", a material's "blend" equation), for scene_json.cpp.
#include "scene/state_json.h"

#include <string>

namespace softraster::scene_json {
namespace {

CompareFunc compare_func(const Node& n) {
    using F = CompareFunc;
    return n.choice<F>({{"never", F::Never}, {"less", F::Less}, {"equal", F::Equal}, {"less_equal", F::LessEqual},
                        {"greater", F::Greater}, {"not_equal", F::NotEqual}, {"greater_equal", F::GreaterEqual},
                        {"always", F::Always}});
}

BlendFactor blend_factor(const Node& n) {
    using F = BlendFactor;
    return n.choice<F>({{"zero", F::Zero}, {"one", F::One}, {"src_color", F::SrcColor},
                        {"one_minus_src_color", F::OneMinusSrcColor}, {"dst_color", F::DstColor},
                        {"one_minus_dst_color", F::OneMinusDstColor}, {"src_alpha", F::SrcAlpha},
                        {"one_minus_src_alpha", F::OneMinusSrcAlpha}, {"dst_alpha", F::DstAlpha},
                        {"one_minus_dst_alpha", F::OneMinusDstAlpha}, {"constant_color", F::ConstantColor},
                        {"one_minus_constant_color", F::OneMinusConstantColor}, {"constant_alpha", F::ConstantAlpha},
                        {"one_minus_constant_alpha", F::OneMinusConstantAlpha}, {"src_alpha_saturate", F::SrcAlphaSaturate}});
}

BlendEquation blend_equation(const Node& n) {
    using E = BlendEquation;
    return n.choice<E>({{"add", E::Add}, {"subtract", E::Subtract}, {"reverse_subtract", E::ReverseSubtract},
                        {"min", E::Min}, {"max", E::Max}});
}

StencilOp stencil_op(const Node& n) {
    using O = StencilOp;
    return n.choice<O>({{"keep", O::Keep}, {"zero", O::Zero}, {"replace", O::Replace}, {"incr", O::Incr},
                        {"incr_wrap", O::IncrWrap}, {"decr", O::Decr}, {"decr_wrap", O::DecrWrap}, {"invert", O::Invert}});
}

// glBlendEquationSeparate + glBlendFuncSeparate + glBlendColor as an object; the alpha
// settings default to the color ones.
// Screen-space ambient occlusion (docs/scene-format.md "Ambient occlusion").

void read_stencil_face(const Node& n, StencilFace& f) {
    n.expect_object({"func", "ref", "read_mask", "write_mask", "fail", "depth_fail", "pass"});
    if (n.has("func")) f.func = compare_func(n["func"]);
    if (n.has("ref")) f.ref = uint8_t(n["ref"].integer_in(0, 255));
    if (n.has("read_mask")) f.read_mask = uint8_t(n["read_mask"].integer_in(0, 255));
    if (n.has("write_mask")) f.write_mask = uint8_t(n["write_mask"].integer_in(0, 255));
    if (n.has("fail")) f.fail = stencil_op(n["fail"]);
    if (n.has("depth_fail")) f.depth_fail = stencil_op(n["depth_fail"]);
    if (n.has("pass")) f.pass = stencil_op(n["pass"]);
}

}  // namespace

BlendEquationState read_blend_equation(const Node& n) {
    n.expect_object({"equation", "equation_alpha", "src", "dst", "src_alpha", "dst_alpha", "constant"});
    BlendEquationState b;
    if (n.has("equation")) b.rgb = blend_equation(n["equation"]);
    b.alpha = n.has("equation_alpha") ? blend_equation(n["equation_alpha"]) : b.rgb;
    if (n.has("src")) b.src_rgb = blend_factor(n["src"]);
    if (n.has("dst")) b.dst_rgb = blend_factor(n["dst"]);
    b.src_alpha = n.has("src_alpha") ? blend_factor(n["src_alpha"]) : b.src_rgb;
    b.dst_alpha = n.has("dst_alpha") ? blend_factor(n["dst_alpha"]) : b.dst_rgb;
    if (n.has("constant")) {
        b.constant = n["constant"].vec4();
        for (int c = 0; c < 4; ++c)
            if (b.constant[c] < 0.0f || b.constant[c] > 1.0f) n["constant"].fail("components must be in [0, 1]");
    }
    return b;
}

void read_depth(const Node& n, ObjectState& st) {
    n.expect_object({"test", "func", "write", "offset"});
    if (n.has("test")) st.depth_test = n["test"].boolean();
    if (n.has("func")) st.depth_func = compare_func(n["func"]);
    if (n.has("write")) st.depth_write = n["write"].boolean();
    if (n.has("offset")) {
        const auto o = n["offset"].numbers<2>();
        st.offset_factor = float(o[0]);
        st.offset_units = float(o[1]);
    }
}

// Either one face state for both faces, or "front" and "back".
void read_stencil(const Node& n, ObjectState& st) {
    st.stencil_test = true;
    if (n.raw().is_object() && (n.has("front") || n.has("back"))) {
        n.expect_object({"front", "back"});
        if (n.has("front")) read_stencil_face(n["front"], st.stencil_front);
        if (n.has("back")) read_stencil_face(n["back"], st.stencil_back);
        return;
    }
    read_stencil_face(n, st.stencil_front);
    st.stencil_back = st.stencil_front;
}

}  // namespace softraster::scene_json
