// Pipeline state a draw runs with: the fixed-function switches of an OpenGL-like API.
#pragma once

namespace softraster {

enum class CullMode { None, Back, Front };
// Winding of front faces as they appear in the displayed picture (OpenGL window coordinates).
enum class FrontFace { CCW, CW };
enum class DepthFunc { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };
// Opaque replaces; Alpha is src*a + dst*(1-a); Additive is src*a + dst (alpha kept).
enum class BlendMode { Opaque, Alpha, Additive };

struct RenderState {
    CullMode cull = CullMode::Back;
    FrontFace front_face = FrontFace::CCW;
    bool depth_test = true;
    DepthFunc depth_func = DepthFunc::Less;
    bool depth_write = true;
    BlendMode blend = BlendMode::Opaque;
    bool color_write = true;
};

}  // namespace softraster
