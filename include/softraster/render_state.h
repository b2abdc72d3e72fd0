// Pipeline state a draw runs with: the fixed-function switches of an OpenGL-like API.
//
// Draws whose state the fast back end handles (tile_back_end.h: depth test and offset, any
// blend equation, color on or off, 1 or 4 samples) run there; anything else (stencil, a
// partial color mask, alpha cutoff, alpha-to-coverage, 2, 8 or 16 samples, blending into
// an sRGB framebuffer) runs in the
// general back end (general_back_end.h), so scenes that do not use a
// feature pay nothing for it (needs_general_back_end below).
#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

namespace softraster {

enum class CullMode { None, Back, Front };
// Winding of front faces as they appear in the displayed picture (OpenGL window coordinates).
enum class FrontFace { CCW, CW };
// GL's eight comparison functions, for depth and for stencil.
enum class CompareFunc { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };
using DepthFunc = CompareFunc;
// The blend presets of scene format v1. Opaque replaces; Alpha is src*a + dst*(1-a);
// Additive is src*a + dst (alpha kept). Custom: the equations of RenderState::blend_equation.
enum class BlendMode { Opaque, Alpha, Additive, Custom };

// glBlendEquationSeparate and glBlendFuncSeparate's values.
enum class BlendEquation { Add, Subtract, ReverseSubtract, Min, Max };
enum class BlendFactor {
    Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor, SrcAlpha, OneMinusSrcAlpha,
    DstAlpha, OneMinusDstAlpha, ConstantColor, OneMinusConstantColor, ConstantAlpha, OneMinusConstantAlpha,
    SrcAlphaSaturate
};
struct BlendEquationState {
    BlendEquation rgb = BlendEquation::Add, alpha = BlendEquation::Add;
    BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
    BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
    glm::vec4 constant{0.0f};  // glBlendColor
};
// The settings a preset stands for (Opaque and Custom: replace, the GL default).
inline BlendEquationState blend_preset(BlendMode mode) {
    using F = BlendFactor;
    BlendEquationState b;
    if (mode == BlendMode::Alpha) b.src_rgb = F::SrcAlpha, b.dst_rgb = F::OneMinusSrcAlpha, b.src_alpha = F::One, b.dst_alpha = F::OneMinusSrcAlpha;
    if (mode == BlendMode::Additive) b.src_rgb = F::SrcAlpha, b.dst_rgb = F::One, b.src_alpha = F::Zero, b.dst_alpha = F::One;
    return b;
}

// glStencilOp's values. Incr and Decr saturate at 255 and 0; the Wrap forms wrap around.
enum class StencilOp { Keep, Zero, Replace, Incr, IncrWrap, Decr, DecrWrap, Invert };
// One face's stencil state (glStencilFuncSeparate, glStencilMaskSeparate, glStencilOpSeparate).
struct StencilFace {
    CompareFunc func = CompareFunc::Always;
    uint8_t ref = 0, read_mask = 0xff, write_mask = 0xff;
    StencilOp fail = StencilOp::Keep, depth_fail = StencilOp::Keep, pass = StencilOp::Keep;
};

// Which vertex of a primitive gives its flat varyings (glProvokingVertex).
enum class ProvokingVertex { First, Last };

// A rectangle of the picture in pixels, x right and y down from the top-left corner.
struct ScissorRect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct RenderState {
    CullMode cull = CullMode::Back;
    FrontFace front_face = FrontFace::CCW;
    bool depth_test = true;
    DepthFunc depth_func = DepthFunc::Less;
    bool depth_write = true;
    // glPolygonOffset: each triangle's window depth moves by
    // factor * max(|dz/dx|, |dz/dy|) + units * 2^(e - 23), e the exponent of its largest |z|.
    float polygon_offset_factor = 0.0f, polygon_offset_units = 0.0f;
    bool stencil_test = false;
    StencilFace stencil_front, stencil_back;
    BlendMode blend = BlendMode::Opaque;
    BlendEquationState blend_equation;  // used when blend is Custom
    bool color_write = true;            // false: no color at all (the fast back end's switch)
    uint8_t color_mask = 0xf;           // bits r, g, b, a (glColorMask), when color_write
    bool alpha_test = false;            // discard fragments whose alpha < alpha_cutoff
    float alpha_cutoff = 0.5f;
    bool alpha_to_coverage = false;     // with MSAA: alpha decides how many samples are covered
    bool noperspective = false;         // varyings interpolated linearly in window space (affine)
    ProvokingVertex provoking_vertex = ProvokingVertex::Last;  // OpenGL's default
    float line_width = 1.0f;            // pixels (line_point_quads.h)
    float point_size = 1.0f;            // pixels
    bool scissor_test = false;
    ScissorRect scissor;
};

// Whether a draw needs the general back end (see the top of this file). Blending into an
// sRGB framebuffer does too: it blends in float, in linear light (output_merge.h).
inline bool needs_general_back_end(const RenderState& s, int samples, bool srgb = false) {
    return s.stencil_test || (s.color_write && s.color_mask != 0xf) || s.alpha_test ||
           s.alpha_to_coverage || (samples != 1 && samples != 4) || (srgb && s.blend != BlendMode::Opaque);
}

}  // namespace softraster
