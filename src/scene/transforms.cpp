// Model, view and projection matrices of the scene format (spec "The pipeline, exactly"),
// computed in double precision and stored as float.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/scene/scene.h"

namespace softraster {

glm::dmat4 rotate_euler(const glm::dmat4& m, const glm::dvec3& rotate_deg) {
    const glm::dmat4 I(1.0);
    const glm::dvec3 r = glm::radians(rotate_deg);
    // Right-handed rotations: glm::rotate turns counter-clockwise looking down the axis.
    return m * glm::rotate(I, r.z, glm::dvec3(0, 0, 1)) * glm::rotate(I, r.y, glm::dvec3(0, 1, 0)) * glm::rotate(I, r.x, glm::dvec3(1, 0, 0));
}

glm::mat4 model_matrix(const glm::vec3& translate, const glm::vec3& rotate_deg, const glm::vec3& scale) {
    const glm::dmat4 I(1.0);
    const glm::dmat4 m = rotate_euler(glm::translate(I, glm::dvec3(translate)), glm::dvec3(rotate_deg)) * glm::scale(I, glm::dvec3(scale));
    return glm::mat4(m);
}

glm::mat4 view_matrix(const Camera& c) {  // gluLookAt
    return glm::mat4(glm::lookAtRH(glm::dvec3(c.eye), glm::dvec3(c.target), glm::dvec3(c.up)));
}

std::array<std::array<double, 3>, 3> camera_intrinsics(const Camera& c, int width, int height) {
    std::array<std::array<double, 3>, 3> k{};
    if (c.orthographic) return k;
    const double f = 0.5 * height / std::tan(glm::radians(double(c.fov_y)) * 0.5);
    k[0] = {f, 0.0, 0.5 * width};
    k[1] = {0.0, f, 0.5 * height};
    k[2] = {0.0, 0.0, 1.0};
    return k;
}

float view_distance(float z, const Camera& c) {
    if (z >= 1.0f) return std::numeric_limits<float>::infinity();
    // Window z = (ndc z + 1) / 2, and ndc z the projection of the view-space depth d:
    // perspective ndc = ((f + n) - 2 n f / d) / (f - n); orthographic ndc = (2 d - f - n) / (f - n).
    const double n = c.near, f = c.far, ndc = 2.0 * z - 1.0;
    if (c.orthographic) return float(0.5 * ((f - n) * ndc + f + n));
    return float(2.0 * n * f / ((f + n) - ndc * (f - n)));
}

glm::dmat3 normal_matrix(const glm::mat4& model) { return glm::transpose(glm::inverse(glm::dmat3(glm::dmat4(model)))); }

std::array<std::array<double, 4>, 4> world_to_camera_gl(const Camera& c) {
    const glm::mat4 view = view_matrix(c);
    std::array<std::array<double, 4>, 4> m{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[size_t(i)][size_t(j)] = double(view[j][i]);  // (glm: column-major)
    return m;
}

std::array<std::array<double, 4>, 4> world_to_camera_cv(const Camera& c) {
    std::array<std::array<double, 4>, 4> m = world_to_camera_gl(c);
    for (size_t j = 0; j < 4; ++j) m[1][j] = -m[1][j], m[2][j] = -m[2][j];
    return m;
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

Bounds shadow_bounds(const Scene& scene) {
    Bounds b;
    for (const SceneObject& o : scene.objects) {
        if (o.primitive != Topology::Triangles) continue;
        for (const MeshVertex& v : o.mesh->vertices) {
            const glm::vec3 p = glm::vec3(o.model * glm::vec4(v.position, 1.0f));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
            b.lo = b.empty() ? p : glm::min(b.lo, p);
            b.hi = b.empty() ? p : glm::max(b.hi, p);
        }
    }
    return b;
}

namespace {
// The light's up vector for lookAt: +y, or +z when the light is within about 8 degrees of vertical.
glm::dvec3 shadow_up(const glm::dvec3& d) { return std::abs(d.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0); }

// Perspective from the light's position p along D, fov degrees wide; far reaches the
// bounds' farthest corner (times 1.01), near is far / 100.
glm::mat4 light_perspective(const glm::dvec3& p, const glm::dvec3& d, double fov, const Bounds& b) {
    double far = 1e-3;
    for (int k = 0; k < 8 && !b.empty(); ++k) {
        const glm::dvec3 corner((k & 1 ? b.hi : b.lo).x, (k & 2 ? b.hi : b.lo).y, (k & 4 ? b.hi : b.lo).z);
        far = std::max(far, glm::length(corner - p));
    }
    far *= 1.01;
    const glm::dmat4 view = glm::lookAtRH(p, p + d, shadow_up(d));
    return glm::mat4(glm::perspectiveRH_NO(glm::radians(fov), 1.0, far / 100.0, far) * view);
}
}  // namespace

// Orthographic, around the bounds' sphere (center c, radius r): the eye 2r behind c.
glm::mat4 shadow_matrix(const DirectionalLight& light, const Bounds& b) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(light.direction));
    const glm::dvec3 c = b.empty() ? glm::dvec3(0.0) : 0.5 * (glm::dvec3(b.lo) + glm::dvec3(b.hi));
    const double r = std::max(1e-3, b.empty() ? 0.0 : 0.5 * glm::length(glm::dvec3(b.hi) - glm::dvec3(b.lo)));
    const glm::dmat4 view = glm::lookAtRH(c - 2.0 * r * d, c, shadow_up(d));
    return glm::mat4(glm::orthoRH_NO(-r, r, -r, r, r, 3.0 * r) * view);
}

// A spot light: along the cone's axis, 2 x outer_angle wide.
glm::mat4 shadow_matrix(const PunctualLight& light, const Bounds& b) {
    return light_perspective(glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)),
                             2.0 * double(light.outer_angle), b);
}

glm::vec3 cube_face_axis(int face) {
    glm::vec3 a(0.0f);
    a[face / 2] = face % 2 ? -1.0f : 1.0f;
    return a;
}

glm::vec3 shadow_offset(const ShadowSettings& s, const glm::vec3& travel) {
    return glm::vec3(-double(s.bias) * glm::normalize(glm::dvec3(travel)));
}

// A point light's cube face: 90 degrees wide, so the six frusta meet edge to edge.
glm::mat4 shadow_matrix(const PunctualLight& light, const Bounds& b, int face) {
    return light_perspective(glm::dvec3(light.position), glm::dvec3(cube_face_axis(face)), 90.0, b);
}

}  // namespace softraster
