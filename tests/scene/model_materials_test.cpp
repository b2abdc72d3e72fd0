// What the model loader takes from a glTF file for the pbr shading and the lights
// (docs/scene-format.md "Model files"): tests/scenes/models/pbr_lights.gltf, written by
// tests/scenes/make_model_scenes.py with known values.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "softraster/scene/model.h"

using namespace softraster;

namespace {
const std::string kModel = std::string(SOFTRASTER_TEST_DATA) + "/scenes/models/pbr_lights.gltf";
}

TEST(ModelMaterials, GltfMaterialsAreMetallicRoughness) {
    const Model m = load_model(kModel);
    ASSERT_EQ(m.objects.size(), 3u);
    const Material& floor = m.objects[0].material;
    EXPECT_EQ(floor.shading, Shading::Pbr);
    EXPECT_FLOAT_EQ(floor.metallic, 0.0f);
    EXPECT_FLOAT_EQ(floor.roughness, 0.6f);
    EXPECT_TRUE(floor.metallic_roughness_texture != nullptr);
    ASSERT_TRUE(floor.occlusion_texture != nullptr);
    EXPECT_FLOAT_EQ(floor.occlusion_strength, 0.7f);
    EXPECT_TRUE(floor.emissive_texture == nullptr);
    const Material& gold = m.objects[1].material;
    EXPECT_FLOAT_EQ(gold.metallic, 1.0f);
    EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
    const Material& lamp = m.objects[2].material;
    EXPECT_TRUE(lamp.emissive_texture != nullptr);
    EXPECT_NEAR(lamp.emissive.y, 0.9f, 1e-6f);
    EXPECT_FLOAT_EQ(lamp.roughness, 1.0f);       // glTF's default
}

TEST(ModelMaterials, GltfLightsArePlacedByTheirNodes) {
    const Model m = load_model(kModel);
    ASSERT_EQ(m.lights.directional.size(), 1u);
    EXPECT_NEAR(m.lights.directional[0].color.x, 0.8f, 1e-5f);  // color times intensity
    EXPECT_LT(m.lights.directional[0].direction.y, -0.5f);      // turned down by its node
    ASSERT_EQ(m.lights.punctual.size(), 2u);
    const PunctualLight& point = m.lights.punctual[0];
    EXPECT_FALSE(point.spot);
    EXPECT_NEAR(glm::distance(point.position, glm::vec3(1.5f, 1.2f, 1.0f)), 0.0f, 1e-5f);
    EXPECT_NEAR(point.color.z, 6.0f, 1e-5f);
    const PunctualLight& spot = m.lights.punctual[1];
    EXPECT_TRUE(spot.spot);
    EXPECT_NEAR(glm::distance(spot.position, glm::vec3(-0.5f, 3.0f, 0.5f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::normalize(spot.direction).y, -1.0f, 1e-3f);  // -z turned -90 degrees about x
    EXPECT_NEAR(spot.inner_angle, glm::degrees(0.3f), 1e-3f);
    EXPECT_NEAR(spot.outer_angle, glm::degrees(0.6f), 1e-3f);
    // render MODEL lights the picture with them instead of the default rig.
    const Scene s = model_scene(m, ModelPicture{});
    EXPECT_EQ(s.lights.punctual.size(), 2u);
    EXPECT_EQ(s.lights.directional.size(), 1u);
    EXPECT_FALSE(s.lights.punctual[0].shadow || s.lights.punctual[1].shadow || s.lights.directional[0].shadow);
    // --shadows: each of them has a map, the point light a cube.
    ModelPicture shadows;
    shadows.shadows = true;
    const Scene shadowed = model_scene(m, shadows);
    EXPECT_TRUE(shadowed.lights.directional[0].shadow && shadowed.lights.punctual[0].shadow && shadowed.lights.punctual[1].shadow);
}

// tests/scenes/models/normal_mapped.gltf: a floor with a normal map and no tangents, a cube
// with a scaled normal map and TANGENT along each face's v axis.
TEST(ModelMaterials, GltfNormalMapsTheirScaleAndTheFilesTangents) {
    const Model m = load_model(std::string(SOFTRASTER_TEST_DATA) + "/scenes/models/normal_mapped.gltf");
    ASSERT_EQ(m.objects.size(), 2u);
    const SceneObject &floor = m.objects[0], &cube = m.objects[1];
    ASSERT_TRUE(floor.material.normal_texture != nullptr);
    EXPECT_FLOAT_EQ(floor.material.normal_scale, 1.0f);
    EXPECT_FLOAT_EQ(cube.material.normal_scale, 0.7f);
    // The floor's are generated: along +u, which the file's uv runs along +x.
    ASSERT_EQ(floor.mesh->tangent_vertices.size(), floor.mesh->vertices.size());
    for (const TangentVertex& v : floor.mesh->tangent_vertices) {
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
    // The cube's are the file's: perpendicular to what generation would give (along u).
    ASSERT_EQ(cube.mesh->tangent_vertices.size(), cube.mesh->vertices.size());
    for (size_t i = 0; i + 3 < cube.mesh->vertices.size(); i += 4) {
        const glm::vec3 t(cube.mesh->tangent_vertices[i].tangent);
        const glm::vec3 along_v = cube.mesh->vertices[i + 3].position - cube.mesh->vertices[i].position;
        EXPECT_NEAR(glm::dot(t, glm::normalize(along_v)), 1.0f, 1e-5f) << "face " << i / 4;
    }
}
