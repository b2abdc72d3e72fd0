// What the surface shaders read: the shading model (the scene format's "shading", spec
// "Shading") and the vertex of a mesh. The scene layer (scene/mesh.h, scene/scene.h) builds
// on these; the shaders need nothing of the scene.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace softraster {

enum class Shading { Unlit, Flat, Gouraud, Lambert, BlinnPhong, Normals, Depth, Phong, Pbr };

struct MeshVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};                 // missing texture coordinates: (0, 0)
    glm::vec4 color{1.0f};              // missing vertex colors: white
};

// A vertex of a normal-mapped mesh: its tangent along +u in xyz, and in w the sign (+1 or
// -1) that makes the bitangent, along +v, w · cross(normal, tangent) (glTF's TANGENT).
// (The same members as MeshVertex, then the tangent: a plain struct, for vertex buffers.)
struct TangentVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};
    glm::vec4 color{1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};

    static TangentVertex of(const MeshVertex& v, const glm::vec4& tangent) { return {v.position, v.normal, v.uv, v.color, tangent}; }
};

}  // namespace softraster
