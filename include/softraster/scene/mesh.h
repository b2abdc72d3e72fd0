// Triangle meshes as the scene format defines them: every vertex has a position, normal,
// texture coordinate and color, and triangles keep the order of the file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace softraster {

struct MeshVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};                 // missing texture coordinates: (0, 0)
    glm::vec4 color{1.0f};              // missing vertex colors: white
};

struct Mesh {
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;  // three per triangle

    size_t triangle_count() const { return indices.size() / 3; }
    // Appends triangle (a, b, c) with fresh corners that all carry its face normal
    // normalize(cross(b - a, c - a)): the rule for triangles without vertex normals.
    void add_face_normal_triangle(MeshVertex a, MeshVertex b, MeshVertex c);
};

// Loaders. Each throws InputError("<path>:<line>: <what>") for a file it cannot use.
Mesh load_obj(const std::filesystem::path& path);
Mesh load_ply(const std::filesystem::path& path);
// By extension: .obj or .ply.
Mesh load_mesh(const std::filesystem::path& path);

}  // namespace softraster
