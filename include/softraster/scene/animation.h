// Scenes that change with time (docs/scene-format.md "Animation"): keyframes, which move
// objects and the camera along tracks of keys, and the turntable, which turns every object
// about the vertical axis through the camera's target while the camera and the lights stay
// where they are, as a model on a turntable in a photo studio.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <glm/ext/quaternion_double.hpp>

#include "softraster/scene/scene.h"

namespace softraster {

// ---- keyframes

// How a track moves between two keys: holding the earlier key's value (step), in a straight
// line (linear; slerp for quaternions), or on a cubic Hermite curve through the keys whose
// slope at each inner key is that of the line through its two neighbours and zero at the
// first and last key (smooth: it eases in and out at the ends and never stops in between).
enum class Interpolation { Step, Linear, Smooth };

// Values at keys, times in seconds strictly increasing. Before the first key the value is
// the first key's, after the last key the last key's; an empty track has no value.
template <class V>
struct Track {
    std::vector<double> times;
    std::vector<V> values;
    bool empty() const { return times.empty(); }
    double end() const { return times.empty() ? 0.0 : times.back(); }
};

glm::dvec3 sample(const Track<glm::dvec3>& track, Interpolation how, double time);
glm::dquat sample(const Track<glm::dquat>& track, Interpolation how, double time);  // (smooth: as linear)

// One node's own transform over time, T(t) * R(t) * S(t). Each part comes from its track,
// or is the rest value where the track is empty. The rotation is Euler angles in degrees
// (R = Rz * Ry * Rx, scene files) or a unit quaternion (glTF files).
struct NodeMotion {
    Interpolation interpolation = Interpolation::Linear;
    Track<glm::dvec3> translate, scale, euler;
    Track<glm::dquat> rotation;
    glm::dvec3 rest_translate{0.0}, rest_scale{1.0};
    glm::dmat4 rest_rotation{1.0};
    double end() const;  // the last key's time
    glm::dmat4 matrix(double time) const;
};

// An object's model matrix over time: the product of its links, outermost first (a node's
// parents before it). A link is a fixed matrix, or a node's motion where one is given.
struct MotionLink {
    glm::dmat4 fixed{1.0};
    std::shared_ptr<const NodeMotion> motion;
};
struct ObjectMotion {
    std::vector<MotionLink> links;
    double end() const;
    glm::mat4 model(double time) const;  // in double precision, rounded to float once
};

// The camera's eye and target over time (up, field of view and planes stay).
struct CameraMotion {
    Interpolation interpolation = Interpolation::Linear;
    Track<glm::dvec3> eye, target;
    double end() const;
};

// The time of the scene's last key: 0 when nothing moves.
double animation_length(const Scene& scene);

// The scene at `time` seconds: every object with a motion takes its model matrix at that
// time, the camera its eye and target. (A scene without keyframes comes back as it is.)
Scene scene_at(const Scene& scene, double time);

// ---- the turntable

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

// ---- both

// What `softraster animate` shows at `time` seconds (and `render --time`): the keyframes at
// that time, then turned by the turntable, if there is one.
Scene frame_at(const Scene& scene, double time, const std::optional<Turntable>& turntable);

}  // namespace softraster
