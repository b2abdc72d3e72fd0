// Built-in meshes: the spec's vertex formulas, counts and orientation (counter-clockwise seen
// from outside: face normals point the way of the vertex normals).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "softraster/scene/builtin_meshes.h"

using namespace softraster;

namespace {
void expect_outward(const Mesh& m) {
    int checked = 0;
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const MeshVertex &a = m.vertices[m.indices[i]], &b = m.vertices[m.indices[i + 1]], &c = m.vertices[m.indices[i + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::length(n) < 1e-9f) continue;  // sphere poles
        EXPECT_GT(glm::dot(n, a.normal + b.normal + c.normal), 0.0f) << "triangle " << i / 3;
        ++checked;
    }
    EXPECT_GT(checked, 0);
}
}  // namespace

TEST(BuiltinMeshes, Plane) {
    const Mesh m = make_plane(4, 2);
    EXPECT_EQ(m.vertices.size(), 9u);
    EXPECT_EQ(m.triangle_count(), 8u);
    EXPECT_EQ(m.vertices[0].position, glm::vec3(-2, 0, 2));  // (i, j) = (0, 0)
    EXPECT_EQ(m.vertices[1].position, glm::vec3(-2, 0, 0));  // (0, 1): j along z
    EXPECT_EQ(m.vertices[3].uv, glm::vec2(0.5f, 0));         // (1, 0)
    expect_outward(m);
}

TEST(BuiltinMeshes, UvSphere) {
    const Mesh m = make_uv_sphere(2, 4, 8);
    EXPECT_EQ(m.vertices.size(), 5u * 9u);
    EXPECT_EQ(m.triangle_count(), 4u * 8u * 2u);  // pole triangles are still emitted
    EXPECT_EQ(m.vertices[0].position, glm::vec3(0, 2, 0));
    EXPECT_EQ(m.vertices[0].uv, glm::vec2(0, 1));
    const MeshVertex& eq = m.vertices[2 * 9 + 2];  // theta = pi/2, phi = pi/2
    EXPECT_NEAR(eq.position.z, -2.0f, 1e-6f);
    expect_outward(m);
}

TEST(BuiltinMeshes, Torus) {
    const Mesh m = make_torus(1, 0.25, 3, 4);
    EXPECT_EQ(m.vertices.size(), 4u * 5u);
    EXPECT_EQ(m.triangle_count(), 24u);
    EXPECT_EQ(m.vertices[0].position, glm::vec3(1.25f, 0, 0));
    expect_outward(make_torus(1, 0.25, 48, 24));
}

TEST(BuiltinMeshes, Cube) {
    const Mesh m = make_cube(2);
    EXPECT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.triangle_count(), 12u);
    // +x face: U = -z, W = +y; first corner h (N - U - W) = (1, -1, 1).
    EXPECT_EQ(m.vertices[0].position, glm::vec3(1, -1, 1));
    EXPECT_EQ(m.vertices[2].uv, glm::vec2(1, 1));
    expect_outward(m);
}
