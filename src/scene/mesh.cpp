#include "softraster/scene/mesh.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "softraster/error.h"

namespace softraster {

void Mesh::add_face_normal_triangle(MeshVertex a, MeshVertex b, MeshVertex c) {
    const glm::vec3 n = glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
    a.normal = b.normal = c.normal = n;
    const auto base = uint32_t(vertices.size());
    vertices.insert(vertices.end(), {a, b, c});
    indices.insert(indices.end(), {base, base + 1, base + 2});
}

Mesh load_mesh(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (ext == ".obj") return load_obj(path);
    if (ext == ".ply") return load_ply(path);
    throw InputError(path.string() + ": unsupported mesh type '" + ext + "' (expected .obj or .ply)");
}

}  // namespace softraster
