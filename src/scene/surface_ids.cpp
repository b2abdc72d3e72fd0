#include "softraster/scene/surface_ids.h"

#include <cmath>
#include <memory>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "softraster/error.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster {
namespace {

constexpr uint32_t kMaxIds = (1u << 24) - 1;  // 0 is the background

// Triangle number `id` (from 1) as a color that the framebuffer stores exactly: r, g and b
// are its bytes, each k / 255 in a linear framebuffer (quantized back to k).
glm::vec4 id_color(uint32_t id) {
    return {float(id & 0xff) / 255.0f, float((id >> 8) & 0xff) / 255.0f, float((id >> 16) & 0xff) / 255.0f, 1.0f};
}

}  // namespace

SurfaceIds surface_ids(const Scene& scene, unsigned threads) {
    Scene pass;
    pass.width = scene.width, pass.height = scene.height;
    pass.background = glm::vec4(0.0f);
    pass.camera = scene.camera;
    pass.sorted = false;  // (all opaque: file order, the depth test decides)
    std::vector<uint32_t> first_id;  // per object: the number of its first triangle
    uint32_t next = 1;
    for (const SceneObject& o : scene.objects) {
        first_id.push_back(next);
        if (o.primitive != Topology::Triangles || !o.mesh) continue;
        const Mesh& mesh = *o.mesh;
        if (mesh.triangle_count() > kMaxIds - next + 1) throw InputError("ids: more than " + std::to_string(kMaxIds) + " triangles");
        auto ids = std::make_shared<Mesh>();  // fresh corners: each triangle one color
        ids->vertices.reserve(mesh.indices.size());
        for (size_t t = 0; t < mesh.triangle_count(); ++t, ++next)
            for (size_t k = 0; k < 3; ++k) {
                MeshVertex v;
                v.position = mesh.vertices[mesh.indices[3 * t + k]].position;
                v.color = id_color(next);
                ids->indices.push_back(uint32_t(ids->vertices.size()));
                ids->vertices.push_back(v);
            }
        SceneObject drawn;
        drawn.mesh = std::move(ids);
        drawn.model = o.model;
        drawn.material.shading = Shading::Unlit;
        drawn.cull = o.cull;
        drawn.front_face = o.front_face;
        pass.objects.push_back(std::move(drawn));
    }
    const Image picture = SceneRenderer(pass, threads).render();
    SurfaceIds out{scene.width, scene.height, std::vector<int32_t>(picture.pixels.size(), -1), std::vector<int32_t>(picture.pixels.size(), -1)};
    for (size_t p = 0; p < picture.pixels.size(); ++p) {
        const Rgba8 c = picture.pixels[p];
        const uint32_t id = uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16;
        if (id == 0) continue;
        // The object: the last whose first triangle is at most id (first_id is ascending).
        size_t lo = 0, hi = first_id.size();
        while (hi - lo > 1) {
            const size_t mid = (lo + hi) / 2;
            (first_id[mid] <= id ? lo : hi) = mid;
        }
        out.object[p] = int32_t(lo);
        out.triangle[p] = int32_t(id - first_id[lo]);
    }
    return out;
}

std::vector<glm::vec3> surface_normals(const Scene& scene, const SurfaceIds& ids, NormalSpace space) {
    // A pixel center's ray: the window point unprojected at the near and far planes.
    const glm::dmat4 view(view_matrix(scene.camera));
    const glm::dmat4 unproject = glm::inverse(glm::dmat4(projection_matrix(scene.camera, scene.width, scene.height)) * view);
    auto world_at = [&](double x, double y, double ndc_z) {
        const glm::dvec4 p = unproject * glm::dvec4(2.0 * x / scene.width - 1.0, 1.0 - 2.0 * y / scene.height, ndc_z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    const glm::dmat3 to_camera = glm::dmat3(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0) * glm::dmat3(view);  // OpenCV's axes
    std::vector<glm::dmat3> normal_matrices;  // per object
    for (const SceneObject& o : scene.objects) normal_matrices.push_back(normal_matrix(o.model));
    std::vector<glm::vec3> out(ids.object.size(), glm::vec3(0.0f));
    for (int y = 0; y < ids.height; ++y)
        for (int x = 0; x < ids.width; ++x) {
            const size_t p = size_t(y) * size_t(ids.width) + size_t(x);
            if (ids.object[p] < 0) continue;
            const SceneObject& o = scene.objects[size_t(ids.object[p])];
            const glm::dmat4 model(o.model);
            const size_t t = size_t(ids.triangle[p]);
            const MeshVertex* v[3];
            glm::dvec3 w[3];
            for (size_t k = 0; k < 3; ++k) {
                v[k] = &o.mesh->vertices[o.mesh->indices[3 * t + k]];
                w[k] = glm::dvec3(model * glm::dvec4(glm::dvec3(v[k]->position), 1.0));
            }
            // The ray o + s d meets the plane at barycentric (b0, b1, b2) (Moller and Trumbore,
            // without the inside test: the center is inside, up to rounding).
            const glm::dvec3 origin = world_at(x + 0.5, y + 0.5, -1.0), dir = world_at(x + 0.5, y + 0.5, 1.0) - origin;
            const glm::dvec3 e1 = w[1] - w[0], e2 = w[2] - w[0], pv = glm::cross(dir, e2);
            const double det = glm::dot(e1, pv);
            glm::dvec3 n;
            if (o.material.shading == Shading::Flat || std::abs(det) < 1e-300) {
                n = glm::cross(e1, e2);
            } else {
                const glm::dvec3 tv = origin - w[0], qv = glm::cross(tv, e1);
                const double b1 = glm::dot(tv, pv) / det, b2 = glm::dot(dir, qv) / det;
                n = normal_matrices[size_t(ids.object[p])] * ((1.0 - b1 - b2) * glm::dvec3(v[0]->normal) + b1 * glm::dvec3(v[1]->normal) + b2 * glm::dvec3(v[2]->normal));
            }
            if (space == NormalSpace::Camera) n = to_camera * n;
            const double len = glm::length(n);
            if (len > 0.0 && std::isfinite(len)) out[p] = glm::vec3(n / len);
        }
    return out;
}

}  // namespace softraster
