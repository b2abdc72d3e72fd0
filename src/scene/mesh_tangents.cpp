// Tangents for normal mapping (docs/scene-format.md "Normal maps").
//
// A tangent-space normal map stores normals in the frame (T, B, N) of the surface, T along
// +u and B along +v of the texture. Per triangle, the edges e1 = p1 − p0, e2 = p2 − p0 and
// their texture coordinate differences (s1, t1), (s2, t2) give the surface's derivatives
//   ∂p/∂u = (t2 e1 − t1 e2) / r,   ∂p/∂v = (s1 e2 − s2 e1) / r,   r = s1 t2 − s2 t1
// (solve e = s ∂p/∂u + t ∂p/∂v for both edges; Lengyel, "Computing Tangent Space Basis
// Vectors for an Arbitrary Mesh", 2001). As MikkTSpace does, each corner adds the unit
// tangent projected into its own normal's plane, weighted by the corner's angle, so a vertex
// shared by long and thin triangles gets their fair share; the bitangents vote the same way
// for the sign w. Unlike MikkTSpace, a vertex is never split: where its triangles disagree
// on the handedness, the weighted majority wins.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "softraster/scene/mesh.h"
#include "softraster/scene/scene.h"

namespace softraster {

namespace {

// The unit vector along v's part perpendicular to unit n, or zero if there is none.
glm::dvec3 in_plane(const glm::dvec3& v, const glm::dvec3& n) {
    const glm::dvec3 p = v - n * glm::dot(n, v);
    const double len = glm::length(p);
    return len > 0.0 && std::isfinite(len) ? p / len : glm::dvec3(0.0);
}

glm::dvec3 unit_normal(const MeshVertex& v) {
    const glm::dvec3 n(v.normal);
    const double len = glm::length(n);
    return len > 0.0 && std::isfinite(len) ? n / len : glm::dvec3(0.0, 0.0, 1.0);
}

// Angle at corner p between the edges to q and r, 0 for a degenerate corner.
double corner_angle(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
    const double lq = glm::length(q - p), lr = glm::length(r - p);
    if (!(lq > 0.0 && lr > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(q - p, r - p) / (lq * lr), -1.0, 1.0));
}

}  // namespace

void generate_tangents(Mesh& mesh) {
    const size_t count = mesh.vertices.size();
    std::vector<glm::dvec3> tangent(count, glm::dvec3(0.0)), bitangent(count, glm::dvec3(0.0));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t idx[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        glm::dvec3 p[3];
        glm::dvec2 uv[3];
        for (int k = 0; k < 3; ++k) p[k] = glm::dvec3(mesh.vertices[idx[k]].position), uv[k] = glm::dvec2(mesh.vertices[idx[k]].uv);
        const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const glm::dvec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
        const double r = d1.x * d2.y - d2.x * d1.y;
        if (r == 0.0 || !std::isfinite(r)) continue;  // no uv area: no direction to give
        const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / r, dpdv = (e2 * d1.x - e1 * d2.x) / r;
        for (int k = 0; k < 3; ++k) {
            const double angle = corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            if (!(angle > 0.0)) continue;
            const glm::dvec3 n = unit_normal(mesh.vertices[idx[k]]);
            tangent[idx[k]] += angle * in_plane(dpdu, n);
            bitangent[idx[k]] += angle * in_plane(dpdv, n);
        }
    }
    mesh.tangent_vertices.resize(count);
    for (size_t v = 0; v < count; ++v) {
        const glm::dvec3 n = unit_normal(mesh.vertices[v]);
        glm::dvec3 t = in_plane(tangent[v], n);
        if (t == glm::dvec3(0.0)) {
            // No triangle gave a direction: any unit vector in the tangent plane, taken from
            // the axis along which n is shortest (never parallel to n).
            const glm::dvec3 a = glm::abs(n);
            const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0) : a.y <= a.z ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
            t = glm::normalize(glm::cross(n, axis));
        }
        const double w = glm::dot(glm::cross(n, t), bitangent[v]) < 0.0 ? -1.0 : 1.0;
        mesh.tangent_vertices[v] = TangentVertex::of(mesh.vertices[v], glm::vec4(glm::vec3(t), float(w)));
    }
}

void add_tangents(std::vector<SceneObject>& objects) {
    std::map<const Mesh*, std::shared_ptr<const Mesh>> with_tangents;
    for (SceneObject& o : objects) {
        if (!o.material.normal_texture || !o.mesh || o.mesh->tangent_vertices.size() == o.mesh->vertices.size()) continue;
        std::shared_ptr<const Mesh>& slot = with_tangents[o.mesh.get()];
        if (!slot) {
            auto copy = std::make_shared<Mesh>(*o.mesh);
            generate_tangents(*copy);
            slot = std::move(copy);
        }
        o.mesh = slot;
    }
}

}  // namespace softraster
