#include "softraster/scene/mesh.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <utility>

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

std::vector<uint32_t> triangle_edges(const Mesh& mesh) {
    std::vector<uint32_t> out;
    std::set<std::pair<uint32_t, uint32_t>> seen;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t a = mesh.indices[i + k], b = mesh.indices[i + (k + 1) % 3];
            if (seen.insert(std::minmax(a, b)).second) out.insert(out.end(), {a, b});
        }
    return out;
}

std::vector<uint32_t> primitive_indices(const Mesh& mesh, Topology primitive) {
    switch (primitive) {
        case Topology::Triangles: return mesh.indices;
        case Topology::Lines: return mesh.lines.empty() ? triangle_edges(mesh) : mesh.lines;
        case Topology::Points: break;
    }
    if (!mesh.points.empty()) return mesh.points;
    std::vector<uint32_t> all(mesh.vertices.size());
    std::iota(all.begin(), all.end(), 0u);
    return all;
}

Mesh load_mesh(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (ext == ".obj") return load_obj(path);
    if (ext == ".ply") return load_ply(path);
    throw InputError(path.string() + ": unsupported mesh type '" + ext + "' (expected .obj or .ply)");
}

}  // namespace softraster
