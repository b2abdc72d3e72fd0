// Stage 5, face culling.
//
// A triangle's winding is the way its corners turn in the displayed picture. Window y grows
// downward here, so the signed area 2A = (x1-x0)(y2-y0) - (y1-y0)(x2-x0) is positive for a
// triangle that turns clockwise on screen and negative for counter-clockwise.
// Zero-area triangles are dropped by triangle setup, whatever the cull mode.
#pragma once
#include "softraster/render_state.h"

namespace softraster {

inline bool is_front_facing(bool ccw_on_screen, FrontFace front) {
    return ccw_on_screen == (front == FrontFace::CCW);
}

inline bool is_culled(bool front_facing, CullMode cull) {
    switch (cull) {
        case CullMode::None: return false;
        case CullMode::Back: return !front_facing;
        case CullMode::Front: return front_facing;
    }
    return false;
}

}  // namespace softraster
