// Scenes that change with time (docs/scene-format.md "Animation"). A turntable turns every
// object about the vertical axis through the camera's target, one full turn per period,
// while the camera and the lights stay where they are, as a model on a turntable in a
// photo studio.
#pragma once
#include "softraster/scene/scene.h"

namespace softraster {

struct Turntable {
    double period = 4.0;  // seconds per full turn, > 0
};

// The angle in degrees the turntable has turned at `time` seconds: 360 time / period, taken
// modulo 360 in double precision (so that frame k of any length of video and `render
// --time` agree to the bit).
double turntable_angle(const Turntable& t, double time);

// The scene at `angle` degrees of the turntable: each object's model matrix M becomes
// T(c) R(u, angle) T(-c) M, with c the camera's target and u its up direction (turning
// counterclockwise seen from above), computed in double precision.
Scene turned_scene(const Scene& scene, double angle);

}  // namespace softraster
