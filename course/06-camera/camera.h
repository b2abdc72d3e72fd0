// Lesson 6: the camera. The matrices that take a point of the world to the screen, written
// out as the tutorials derive them (OpenGL's conventions: right-handed, the camera looking
// down its -z axis, depth in [-1, 1] after the divide).
#pragma once
#include <cmath>

#include <glm/glm.hpp>

namespace course {

// lookAt (观察矩阵): the camera's own axes from where it is (eye), what it looks at (target)
// and which way is up. forward f = normalize(target - eye), right r = normalize(f x up),
// true up u = r x f. The view matrix turns the world so that these become x, y and -z, and
// moves the eye to the origin: its rows are r, u, -f, and its last column is
// (-r.eye, -u.eye, f.eye).
inline glm::mat4 look_at(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 f = glm::normalize(target - eye), r = glm::normalize(glm::cross(f, up)), u = glm::cross(r, f);
    glm::mat4 m(1.0f);  // glm is column-major: m[column][row]
    m[0][0] = r.x, m[1][0] = r.y, m[2][0] = r.z, m[3][0] = -glm::dot(r, eye);
    m[0][1] = u.x, m[1][1] = u.y, m[2][1] = u.z, m[3][1] = -glm::dot(u, eye);
    m[0][2] = -f.x, m[1][2] = -f.y, m[2][2] = -f.z, m[3][2] = glm::dot(f, eye);
    return m;
}

// Perspective projection (透视投影): a point at depth d in front of the camera (z = -d) lands
// on the screen at x / d, y / d, scaled so that the field of view fits: 1 / tan(fov/2)
// (divided by the aspect ratio for x). The division by d is done by the GPU after the
// matrix, by making w = -z. z is mapped so that the near plane goes to -1 and the far plane
// to +1 after the division: z_ndc = (A z + B) / -z with A = -(f + n)/(f - n), B = -2 f n / (f - n).
inline glm::mat4 perspective(float fov_y_degrees, float aspect, float near, float far) {
    const float s = 1.0f / std::tan(glm::radians(fov_y_degrees) / 2.0f);
    glm::mat4 m(0.0f);
    m[0][0] = s / aspect;
    m[1][1] = s;
    m[2][2] = -(far + near) / (far - near);
    m[3][2] = -2.0f * far * near / (far - near);
    m[2][3] = -1.0f;  // w = -z
    return m;
}

// Orthographic projection (正交投影): no division; a box of the given half width and height,
// and near..far, scaled to [-1, 1].
inline glm::mat4 orthographic(float half_width, float half_height, float near, float far) {
    glm::mat4 m(1.0f);
    m[0][0] = 1.0f / half_width;
    m[1][1] = 1.0f / half_height;
    m[2][2] = -2.0f / (far - near);
    m[3][2] = -(far + near) / (far - near);
    return m;
}

// After the matrices: the perspective divide (透视除法) to normalized device coordinates (NDC,
// 标准化设备坐标, all in [-1, 1] inside the view), then the viewport (视口变换) to pixels,
// y flipped (NDC's y goes up, the picture's rows down), and depth to [0, 1].
struct ScreenPoint {
    float x, y, depth;
};
inline ScreenPoint to_screen(const glm::vec4& clip, int width, int height) {
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), (ndc.z + 1.0f) * 0.5f};
}

}  // namespace course
