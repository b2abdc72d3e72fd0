// Stage 5, face culling.
//
// A triangle's winding is the way its corners turn in the displayed picture. Window y grows
// downward here, so the signed area 2A = (x1-x0)(y2-y0) - (y1-y0)(x2-x0) of the snapped
// corners is positive for a triangle that turns clockwise on screen and negative for
// counter-clockwise. A triangle of zero snapped area covers no sample: it is dropped here
// too, whatever the cull mode.
#pragma once
#include <cstdint>

#include "softraster/render_state.h"

namespace softraster {

// Twice the signed area of the snapped triangle: > 0 when it turns clockwise on screen.
inline int64_t signed_area2(int64_t x0, int64_t y0, int64_t x1, int64_t y1, int64_t x2, int64_t y2) {
    return (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
}

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

struct FaceState {
    CullMode cull = CullMode::Back;
    FrontFace front = FrontFace::CCW;
};

// The windings a draw's face state keeps, found once per draw: a triangle is then kept or
// culled by its area's sign alone (binning culls millions a frame).
struct WindingFilter {
    bool keep_cw, keep_ccw;  // on screen
    explicit WindingFilter(FaceState f)
        : keep_cw(!is_culled(is_front_facing(/*ccw_on_screen=*/false, f.front), f.cull)),
          keep_ccw(!is_culled(is_front_facing(/*ccw_on_screen=*/true, f.front), f.cull)) {}
    // Whether a triangle of snapped signed area `area2` goes on down the pipeline.
    bool survives(int64_t area2) const { return area2 > 0 ? keep_cw : area2 < 0 && keep_ccw; }
};

}  // namespace softraster
