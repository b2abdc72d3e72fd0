#include "softraster/scene/builtin_meshes.h"

#include <cmath>
#include <numbers>

namespace softraster {
namespace {

// Cells of a (nu + 1) x (nv + 1) vertex grid, vertex (i, j) at index i * (nv + 1) + j:
// cell (i, j) with a = (i, j), b = (i+1, j), c = (i+1, j+1), e = (i, j+1) gives (a, b, c), (a, c, e).
void add_grid_cells(Mesh& m, int nu, int nv) {
    const auto id = [nv](int i, int j) { return uint32_t(i * (nv + 1) + j); };
    m.indices.reserve(size_t(nu) * size_t(nv) * 6);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), e = id(i, j + 1);
            m.indices.insert(m.indices.end(), {a, b, c, a, c, e});
        }
}

glm::vec3 vec3d(double x, double y, double z) { return glm::vec3(float(x), float(y), float(z)); }

}  // namespace

Mesh make_plane(double s, int d) {
    Mesh m;
    for (int i = 0; i <= d; ++i)
        for (int j = 0; j <= d; ++j) {
            MeshVertex v;
            v.position = vec3d(-s / 2 + s * i / d, 0.0, s / 2 - s * j / d);
            v.uv = glm::vec2(float(double(i) / d), float(double(j) / d));
            v.normal = glm::vec3(0, 1, 0);
            m.vertices.push_back(v);
        }
    add_grid_cells(m, d, d);
    return m;
}

Mesh make_uv_sphere(double radius, int rings, int segments) {
    Mesh m;
    m.vertices.reserve(size_t(rings + 1) * size_t(segments + 1));
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
            const double nx = std::sin(theta) * std::cos(phi), ny = std::cos(theta), nz = -std::sin(theta) * std::sin(phi);
            MeshVertex v;
            v.normal = vec3d(nx, ny, nz);
            v.position = vec3d(radius * nx, radius * ny, radius * nz);
            v.uv = glm::vec2(float(double(s) / segments), float(1.0 - double(r) / rings));
            m.vertices.push_back(v);
        }
    add_grid_cells(m, rings, segments);
    return m;
}

Mesh make_torus(double major, double minor, int rings, int segments) {
    Mesh m;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= segments; ++j) {
            const double u = 2 * std::numbers::pi * i / rings, v = 2 * std::numbers::pi * j / segments;
            MeshVertex vert;
            vert.normal = vec3d(std::cos(v) * std::cos(u), std::sin(v), -std::cos(v) * std::sin(u));
            const double ring = major + minor * std::cos(v);
            vert.position = vec3d(ring * std::cos(u), minor * std::sin(v), -ring * std::sin(u));
            vert.uv = glm::vec2(float(double(i) / rings), float(double(j) / segments));
            m.vertices.push_back(vert);
        }
    add_grid_cells(m, rings, segments);
    return m;
}

Mesh make_cube(double size) {
    struct Face {
        glm::vec3 n, u, w;  // U x W = N
    };
    static constexpr Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    const float h = float(size / 2);
    Mesh m;
    for (const Face& f : faces) {
        const auto base = uint32_t(m.vertices.size());
        const glm::vec3 corners[4] = {f.n - f.u - f.w, f.n + f.u - f.w, f.n + f.u + f.w, f.n - f.u + f.w};
        const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; ++k) m.vertices.push_back({h * corners[k], f.n, uvs[k], glm::vec4(1.0f)});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

}  // namespace softraster
