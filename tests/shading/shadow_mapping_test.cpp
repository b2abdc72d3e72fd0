// Shadow maps (shadow_mapping.h): the lookup and the PCF count against maps written by
// hand, and the eight-lane lookup against the one-point lookup.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/scene/scene.h"
#include "softraster/shading/lighting.h"
#include "softraster/shading/shadow_mapping.h"

using namespace softraster;

namespace {

// A 4 x 4 map seen straight down -z through an orthographic box x, y in [-2, 2], z in [0, 4]
// (view depth d gives window depth d / 4): texel (i, j) covers x in [i - 2, i - 1] and
// y in [1 - j, 2 - j] (row 0 at the top).
struct HandMap {
    std::vector<float> depth = std::vector<float>(16, 1.0f);
    ShadowMap map;
    HandMap(int pcf) {
        map.face[0].depth = depth.data();
        map.size = 4;
        map.face[0].matrix = glm::orthoRH_NO(-2.0f, 2.0f, -2.0f, 2.0f, 0.0f, 4.0f);
        map.pcf = pcf;
    }
    void set(int i, int j, float z) { depth[size_t(j * 4 + i)] = z; }
    float at(float x, float y, float view_depth) const {
        float v;
        shadow_visibility(map, glm::vec3(x, y, -view_depth), v);
        return v;
    }
};

TEST(ShadowMapping, OneTexelComparesDepthAtOrBeyond) {
    HandMap h(0);
    h.set(1, 2, 0.5f);  // an occluder at view depth 2 over x in [-1, 0], y in [-1, 0]
    EXPECT_EQ(h.at(-0.5f, -0.5f, 3.0f), 0.0f);   // behind it
    EXPECT_EQ(h.at(-0.5f, -0.5f, 2.0f), 1.0f);   // on it: z <= D
    EXPECT_EQ(h.at(-0.5f, -0.5f, 1.0f), 1.0f);   // in front
    EXPECT_EQ(h.at(0.5f, -0.5f, 3.0f), 1.0f);    // beside it
    EXPECT_EQ(h.at(-0.5f, 0.5f, 3.0f), 1.0f);    // above it (row 1)
}

TEST(ShadowMapping, PcfIsTheShareOfTheKernelThatIsLit) {
    HandMap h(1);
    h.set(1, 2, 0.5f);
    h.set(2, 2, 0.5f);
    // Centered on texel (1, 2): its 3 x 3 kernel holds both occluders.
    EXPECT_FLOAT_EQ(h.at(-0.5f, -0.5f, 3.0f), 7.0f / 9.0f);
    // On texel (3, 3), the corner: clamped indices read texels (2..3, 2..3) with repeats:
    // (2, 2) once; the rest lit.
    EXPECT_FLOAT_EQ(h.at(1.5f, -1.5f, 3.0f), 8.0f / 9.0f);
    // Far outside the map: the corner texel's kernel, clamped: (0..1, 0..1), all lit; and
    // (0..1, 2..3), which holds (1, 2).
    EXPECT_EQ(h.at(-50.0f, 50.0f, 3.0f), 1.0f);
    EXPECT_FLOAT_EQ(h.at(-50.0f, -50.0f, 3.0f), 8.0f / 9.0f);
}

TEST(ShadowMapping, BiasMovesThePointTowardTheLight) {
    HandMap h(0);
    h.set(1, 2, 0.5f);
    h.map.face[0].offset = glm::vec3(0, 0, 1.5f);       // 1.5 units toward a light at +z
    EXPECT_EQ(h.at(-0.5f, -0.5f, 3.0f), 1.0f);  // looked up at depth 1.5
    EXPECT_EQ(h.at(-0.5f, -0.5f, 3.5f), 1.0f);  // at 2: on the occluder
    EXPECT_EQ(h.at(-0.5f, -0.5f, 3.6f), 0.0f);
}

TEST(ShadowMapping, BehindASpotLightIsLit) {
    std::vector<float> depth(16, 0.0f);  // everything occluded
    ShadowMap m;
    m.face[0].depth = depth.data();
    m.size = 4;
    m.face[0].matrix = glm::perspectiveRH_NO(glm::radians(90.0f), 1.0f, 0.1f, 10.0f);  // looking down -z
    m.pcf = 0;
    float v;
    shadow_visibility(m, glm::vec3(0, 0, 1), v);  // q.w = -1
    EXPECT_EQ(v, 1.0f);
    shadow_visibility(m, glm::vec3(0, 0, -1), v);
    EXPECT_EQ(v, 0.0f);
}

// Eight at once give the same bits as one at a time (the batch and single-fragment shaders).
TEST(ShadowMapping, EightLookupsEqualOneAtATime) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> depth(64 * 64);
    for (float& d : depth) d = 0.3f + 0.4f * u(rng);
    ShadowMap m;
    m.face[0].depth = depth.data();
    m.size = 64;
    m.face[0].matrix = glm::perspectiveRH_NO(glm::radians(60.0f), 1.0f, 0.5f, 8.0f) *
                       glm::lookAtRH(glm::vec3(1, 4, 2), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    m.face[0].offset = glm::vec3(0.01f, 0.02f, 0.005f);
    for (int pcf = 0; pcf <= 2; ++pcf) {
        m.pcf = pcf;
        for (int round = 0; round < 200; ++round) {
            simd::vec3x8 p;
            for (int l = 0; l < simd::kLanes; ++l) p.x[l] = 4 * u(rng) - 2, p.y[l] = 2 * u(rng) - 1, p.z[l] = 4 * u(rng) - 2;
            simd::f8 v8;
            shadow_visibility(m, p, v8);
            for (int l = 0; l < simd::kLanes; ++l) {
                float v;
                shadow_visibility(m, glm::vec3(p.x[l], p.y[l], p.z[l]), v);
                EXPECT_EQ(v, v8[l]);
            }
        }
    }
}

TEST(ShadowMapping, CubeFaceIsTheMajorAxis) {
    ShadowMap m;
    m.light = glm::vec3(1, 2, 3);
    auto face = [&](float x, float y, float z) { return cube_face(m, 1 + x, 2 + y, 3 + z); };
    EXPECT_EQ(face(2, 1, -1), 0);
    EXPECT_EQ(face(-2, 1, -1), 1);
    EXPECT_EQ(face(0.5f, 2, -1), 2);
    EXPECT_EQ(face(0.5f, -2, -1), 3);
    EXPECT_EQ(face(0.5f, -2, 3), 4);
    EXPECT_EQ(face(0.5f, -2, -3), 5);
    // Ties: x before y before z; a zero component counts as +.
    EXPECT_EQ(face(-1, 1, 1), 1);
    EXPECT_EQ(face(0.5f, -1, 1), 3);
    EXPECT_EQ(face(0, 0, 0), 0);
}

// A point light at c with a cube of 8 x 8 faces, each face's depths the caller's.
struct HandCube {
    std::array<std::vector<float>, 6> depth;
    ShadowMap map;
    explicit HandCube(const glm::vec3& c) {
        PunctualLight light;
        light.position = c;
        const Bounds box{c - 4.0f, c + 4.0f};
        map.faces = 6;
        map.light = c;
        map.size = 8;
        map.pcf = 0;
        for (int f = 0; f < 6; ++f) {
            depth[size_t(f)].assign(64, 1.0f);
            map.face[size_t(f)].depth = depth[size_t(f)].data();
            map.face[size_t(f)].matrix = shadow_matrix(light, box, f);
        }
    }
};

// Each face sees its own sixth of the space: an occluder written into one face shadows the
// points in that direction only, and a face's axis projects to its map's center.
TEST(ShadowMapping, ACubeLooksUpTheFaceOfTheMajorAxis) {
    const glm::vec3 c(0.5f, -1.0f, 2.0f);
    for (int occluded = 0; occluded < 6; ++occluded) {
        HandCube cube(c);
        cube.depth[size_t(occluded)].assign(64, 0.0f);
        for (int f = 0; f < 6; ++f) {
            const glm::vec3 axis = cube_face_axis(f);
            ShadowCoords<float> q;
            const glm::vec3 p = c + 2.0f * axis;
            shadow_coords(cube.map.face[size_t(f)], cube.map.size, p.x, p.y, p.z, q);
            EXPECT_NEAR(q.x, 4.0f, 1e-4f);
            EXPECT_NEAR(q.y, 4.0f, 1e-4f);
            EXPECT_GT(q.w, 0.0f);
            // Off the axis but still in face f: 0.9 of the way to its edge.
            const glm::vec3 side = cube_face_axis((f / 2 * 2 + 2) % 6), up = cube_face_axis((f / 2 * 2 + 4) % 6);
            for (const glm::vec3& point : {p, p + 1.8f * side, p - 1.8f * up + 1.8f * side}) {
                float v;
                shadow_visibility(cube.map, point, v);
                EXPECT_EQ(v, f == occluded ? 0.0f : 1.0f) << "face " << f << ", occluded " << occluded;
            }
        }
    }
}

// A cube's eight-lane lookup equals its one-point lookup, lanes in different faces.
TEST(ShadowMapping, EightCubeLookupsEqualOneAtATime) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    HandCube cube(glm::vec3(0.2f, 0.1f, -0.3f));
    for (auto& d : cube.depth)
        for (float& z : d) z = 0.9f + 0.1f * u(rng);
    cube.map.pcf = 1;
    for (int f = 0; f < 6; ++f) cube.map.face[size_t(f)].offset = -0.05f * cube_face_axis(f);
    int shadowed = 0;
    for (int round = 0; round < 200; ++round) {
        simd::vec3x8 p;
        for (int l = 0; l < simd::kLanes; ++l) p.x[l] = 8 * u(rng) - 4, p.y[l] = 8 * u(rng) - 4, p.z[l] = 8 * u(rng) - 4;
        simd::f8 v8;
        shadow_visibility(cube.map, p, v8);
        for (int l = 0; l < simd::kLanes; ++l) {
            float v;
            shadow_visibility(cube.map, glm::vec3(p.x[l], p.y[l], p.z[l]), v);
            EXPECT_EQ(v, v8[l]);
            shadowed += v < 1.0f;
        }
    }
    EXPECT_GT(shadowed, 100);  // the maps' depths do shadow some points
}

// A shadowed light's color times its visibility; the others as before, bit for bit.
TEST(ShadowMapping, VisibilityScalesOnlyTheShadowedLight) {
    std::vector<float> depth(16, 0.0f);
    ShadowMap m;
    m.face[0].depth = depth.data();
    m.size = 4;
    m.face[0].matrix = glm::orthoRH_NO(-2.0f, 2.0f, -2.0f, 2.0f, 0.0f, 4.0f);
    m.pcf = 0;
    LightSet lights;
    lights.ambient = glm::vec3(0.1f);
    lights.count = 2;
    lights.to_light = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0, 1, 1))};
    lights.color = {glm::vec3(0.5f), glm::vec3(0.3f, 0.2f, 0.1f)};
    const glm::vec3 n(0, 0, 1), p(0.5f, 0.5f, -1.0f);
    const glm::vec3 unshadowed = diffuse_intensity(lights, n);
    lights.shadows[0] = &m;
    lights.shadow_count = 1;
    lights.shadow_of[0] = 0;
    LightVisibility<float> vis = kFullyLit;
    light_visibility(lights, p, vis);
    EXPECT_EQ(vis[0], 0.0f);
    glm::vec3 expected = lights.ambient;
    expected += lights.color[1] * std::max(0.0f, glm::dot(n, lights.to_light[1]));
    EXPECT_EQ(diffuse_intensity(lights, n, vis), expected);
    depth.assign(16, 1.0f);
    light_visibility(lights, p, vis);
    EXPECT_EQ(diffuse_intensity(lights, n, vis), unshadowed);
}

}  // namespace
