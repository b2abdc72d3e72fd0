#include "softraster/scene/animation.h"

#include <algorithm>
#include <cmath>

#include <glm/ext/quaternion_common.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace softraster {

namespace {

// The segment [times[k], times[k + 1]] that holds `time` and how far along it is, s in
// [0, 1]; before the first key (k = 0, s = 0), after the last (k = n - 2, s = 1).
struct Segment {
    size_t k = 0;
    double s = 0.0;
};
Segment find_segment(const std::vector<double>& times, double time) {
    if (times.size() < 2 || !(time > times.front())) return {0, 0.0};
    if (time >= times.back()) return {times.size() - 2, 1.0};
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    return {k, (time - times[k]) / (times[k + 1] - times[k])};
}

// Smooth: the slope (per second) at key k, as the class comment in animation.h gives it.
glm::dvec3 slope(const Track<glm::dvec3>& t, size_t k) {
    if (k == 0 || k + 1 == t.times.size()) return glm::dvec3(0.0);
    return (t.values[k + 1] - t.values[k - 1]) / (t.times[k + 1] - t.times[k - 1]);
}

}  // namespace

glm::dvec3 sample(const Track<glm::dvec3>& track, Interpolation how, double time) {
    const Segment g = find_segment(track.times, time);
    const glm::dvec3& a = track.values[g.k];
    if (track.times.size() == 1 || g.s == 0.0) return a;
    const glm::dvec3& b = track.values[g.k + 1];
    if (g.s == 1.0) return b;
    switch (how) {
        case Interpolation::Step: return a;
        case Interpolation::Linear: return a + (b - a) * g.s;
        case Interpolation::Smooth: {
            // Cubic Hermite basis: p(s) = h00 a + h10 h m_a + h01 b + h11 h m_b.
            const double s = g.s, s2 = s * s, s3 = s2 * s, h = track.times[g.k + 1] - track.times[g.k];
            return (2 * s3 - 3 * s2 + 1) * a + (s3 - 2 * s2 + s) * h * slope(track, g.k) + (3 * s2 - 2 * s3) * b +
                   (s3 - s2) * h * slope(track, g.k + 1);
        }
    }
    return a;
}

glm::dquat sample(const Track<glm::dquat>& track, Interpolation how, double time) {
    const Segment g = find_segment(track.times, time);
    const glm::dquat& a = track.values[g.k];
    if (track.times.size() == 1 || g.s == 0.0 || how == Interpolation::Step) return a;
    const glm::dquat& b = track.values[g.k + 1];
    if (g.s == 1.0) return b;
    return glm::slerp(a, b, g.s);  // the shorter way round, as glTF asks
}

double NodeMotion::end() const { return std::max({translate.end(), scale.end(), euler.end(), rotation.end()}); }

glm::dmat4 NodeMotion::matrix(double time) const {
    const glm::dmat4 I(1.0);
    const glm::dmat4 t = glm::translate(I, translate.empty() ? rest_translate : sample(translate, interpolation, time));
    const glm::dmat4 s = glm::scale(I, scale.empty() ? rest_scale : sample(scale, interpolation, time));
    if (!euler.empty()) return rotate_euler(t, sample(euler, interpolation, time)) * s;  // as model_matrix does it
    const glm::dmat4 r = rotation.empty() ? rest_rotation : glm::mat4_cast(sample(rotation, interpolation, time));
    return t * r * s;
}

double ObjectMotion::end() const {
    double end = 0.0;
    for (const MotionLink& l : links)
        if (l.motion) end = std::max(end, l.motion->end());
    return end;
}

glm::mat4 ObjectMotion::model(double time) const {
    glm::dmat4 m(1.0);
    for (const MotionLink& l : links) m = m * (l.motion ? l.motion->matrix(time) : l.fixed);
    return glm::mat4(m);
}

double CameraMotion::end() const { return std::max(eye.end(), target.end()); }

double animation_length(const Scene& scene) {
    double end = scene.camera_motion ? scene.camera_motion->end() : 0.0;
    for (const SceneObject& o : scene.objects)
        if (o.motion) end = std::max(end, o.motion->end());
    return end;
}

Scene scene_at(const Scene& scene, double time) {
    Scene out = scene;
    for (SceneObject& o : out.objects) {
        if (o.motion) o.model = o.motion->model(time);
        o.motion.reset();
    }
    if (const CameraMotion* c = scene.camera_motion.get()) {
        if (!c->eye.empty()) out.camera.eye = glm::vec3(sample(c->eye, c->interpolation, time));
        if (!c->target.empty()) out.camera.target = glm::vec3(sample(c->target, c->interpolation, time));
        out.camera_motion.reset();
    }
    return out;
}

double turntable_angle(const Turntable& t, double time) {
    const double turns = time / t.period;
    return 360.0 * (turns - std::floor(turns));
}

Scene turned_scene(const Scene& scene, double angle) {
    Scene out = scene;
    const glm::dvec3 c(scene.camera.target), up = glm::normalize(glm::dvec3(scene.camera.up));
    const glm::dmat4 turn = glm::translate(glm::dmat4(1.0), c) * glm::rotate(glm::dmat4(1.0), glm::radians(angle), up) *
                            glm::translate(glm::dmat4(1.0), -c);
    for (SceneObject& o : out.objects) o.model = glm::mat4(turn * glm::dmat4(o.model));
    return out;
}

Scene frame_at(const Scene& scene, double time, const std::optional<Turntable>& turntable) {
    Scene out = scene_at(scene, time);
    return turntable ? turned_scene(out, turntable_angle(*turntable, time)) : out;
}

}  // namespace softraster
