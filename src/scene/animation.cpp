#include "softraster/scene/animation.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace softraster {

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

}  // namespace softraster
