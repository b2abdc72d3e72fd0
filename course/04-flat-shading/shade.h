// Lesson 4: flat shading and back-face culling, on lesson 3's edge-function fill.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "../03-triangles/fill.h"

namespace course {

// Flat shading (平面着色): one color per triangle, from the angle between its normal and the
// light. The normal is the cross product of two edges, n = (b - a) x (c - a), normalized;
// Lambert's law makes the brightness cos(angle) = n . l for a unit vector l towards the
// light, 0 when the light is behind (n . l < 0).
inline float lambert(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& to_light) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    return std::max(0.0f, glm::dot(n, glm::normalize(to_light)));
}

// Back-face culling (背面剔除), the way a GPU does it: after projection, a triangle whose
// corners go clockwise on the screen (y down) where the model has them counterclockwise
// seen from outside is seen from behind. The sign of its area (lesson 3's edge function
// E(a, b, c)) tells, with nothing else to compute.
inline bool faces_away_on_screen(Point a, Point b, Point c) { return edge_function(a, b, c) >= 0; }

// The same question in 3D: the normal points away from the viewer. For a view along -z (an
// orthographic camera looking down the z axis), that is n.z <= 0.
inline bool faces_away_in_3d(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) { return glm::cross(b - a, c - a).z <= 0.0f; }

}  // namespace course
