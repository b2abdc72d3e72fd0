// Tangents for normal maps (mesh_tangents.cpp): along +u in each vertex's tangent plane, the
// sign w making w · cross(N, T) point along +v, shared copies for shared meshes.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "softraster/scene/builtin_meshes.h"
#include "softraster/scene/scene.h"
#include "softraster/shading/texture.h"
#include "test_support.h"

using namespace softraster;

namespace {
void expect_near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) { test::expect_near(a, b, eps); }
}  // namespace

TEST(MeshTangents, PlaneTangentIsPlusXAndBitangentPlusV) {
    // The built-in plane: u grows along +x, v along -z, the normal is +y.
    Mesh m = make_plane(2, 3);
    generate_tangents(m);
    ASSERT_EQ(m.tangent_vertices.size(), m.vertices.size());
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const TangentVertex& v = m.tangent_vertices[i];
        expect_near(glm::vec3(v.tangent), glm::vec3(1, 0, 0));
        EXPECT_EQ(v.tangent.w, 1.0f);
        expect_near(v.tangent.w * glm::cross(v.normal, glm::vec3(v.tangent)), glm::vec3(0, 0, -1));
        EXPECT_EQ(v.position, m.vertices[i].position);  // the vertex itself is unchanged
        EXPECT_EQ(v.uv, m.vertices[i].uv);
    }
}

TEST(MeshTangents, MirroredTextureFlipsTheSign) {
    Mesh m = make_plane(2, 2);
    for (MeshVertex& v : m.vertices) v.uv.x = 1.0f - v.uv.x;  // u now grows along -x
    generate_tangents(m);
    for (const TangentVertex& v : m.tangent_vertices) {
        expect_near(glm::vec3(v.tangent), glm::vec3(-1, 0, 0));
        EXPECT_EQ(v.tangent.w, -1.0f);
        expect_near(v.tangent.w * glm::cross(v.normal, glm::vec3(v.tangent)), glm::vec3(0, 0, -1));  // still +v
    }
}

TEST(MeshTangents, SphereTangentsAreUnitAndInTheTangentPlane) {
    Mesh m = make_uv_sphere(1.5f, 12, 24);
    generate_tangents(m);
    for (const TangentVertex& v : m.tangent_vertices) {
        const glm::vec3 t(v.tangent);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, v.normal), 0.0f, 1e-5f);
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
    }
    // On the equator, away from the seam, +u runs along φ: d/dφ of (cos φ, 0, −sin φ).
    const TangentVertex& eq = m.tangent_vertices[size_t(6 * 25 + 6)];  // ring 6 of 12, segment 6 of 24: φ = π/2
    expect_near(glm::vec3(eq.tangent), glm::vec3(-1, 0, 0), 1e-4f);
}

TEST(MeshTangents, NoTextureCoordinatesStillGiveAUnitTangent) {
    Mesh m = make_plane(2, 1);
    for (MeshVertex& v : m.vertices) v.uv = glm::vec2(0.0f);  // no uv area anywhere
    generate_tangents(m);
    for (const TangentVertex& v : m.tangent_vertices) {
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-6f);
    }
}

TEST(MeshTangents, OnlyNormalMappedObjectsGetThemAndShareTheCopy) {
    auto mesh = std::make_shared<const Mesh>(make_plane(2, 1));
    Image img(1, 1);
    auto map = std::make_shared<const Texture>(img);
    std::vector<SceneObject> objects(3);
    for (SceneObject& o : objects) o.mesh = mesh;
    objects[0].material.normal_texture = map;
    objects[2].material.normal_texture = map;
    add_tangents(objects);
    EXPECT_EQ(objects[1].mesh, mesh);  // untouched, and the original has no tangents
    EXPECT_TRUE(mesh->tangent_vertices.empty());
    EXPECT_NE(objects[0].mesh, mesh);
    EXPECT_EQ(objects[0].mesh, objects[2].mesh);
    EXPECT_EQ(objects[0].mesh->tangent_vertices.size(), mesh->vertices.size());
}
