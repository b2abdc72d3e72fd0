// Model, view and projection matrices of the scene format (spec "The pipeline, exactly"),
// computed in double precision and stored as float.
#include <glm/gtc/matrix_transform.hpp>

#include "softraster/scene/scene.h"

namespace softraster {

glm::mat4 model_matrix(const glm::vec3& translate, const glm::vec3& rotate_deg, const glm::vec3& scale) {
    const glm::dmat4 I(1.0);
    const glm::dvec3 r = glm::radians(glm::dvec3(rotate_deg));
    // Right-handed rotations: glm::rotate turns counter-clockwise looking down the axis.
    const glm::dmat4 m = glm::translate(I, glm::dvec3(translate)) * glm::rotate(I, r.z, glm::dvec3(0, 0, 1)) *
                         glm::rotate(I, r.y, glm::dvec3(0, 1, 0)) * glm::rotate(I, r.x, glm::dvec3(1, 0, 0)) *
                         glm::scale(I, glm::dvec3(scale));
    return glm::mat4(m);
}

glm::mat4 view_matrix(const Camera& c) {  // gluLookAt
    return glm::mat4(glm::lookAtRH(glm::dvec3(c.eye), glm::dvec3(c.target), glm::dvec3(c.up)));
}

glm::mat4 projection_matrix(const Camera& c, int width, int height) {
    const double aspect = double(width) / double(height);
    if (c.orthographic) {  // glOrtho(-h a / 2, h a / 2, -h / 2, h / 2, near, far)
        const double h = c.height;
        return glm::mat4(glm::orthoRH_NO(-h * aspect / 2, h * aspect / 2, -h / 2, h / 2, double(c.near), double(c.far)));
    }
    // gluPerspective
    return glm::mat4(glm::perspectiveRH_NO(glm::radians(double(c.fov_y)), aspect, double(c.near), double(c.far)));
}

}  // namespace softraster
