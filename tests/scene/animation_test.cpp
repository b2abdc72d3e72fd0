// Keyframes (scene/animation.h): the interpolation of tracks against values worked out by
// hand, scene files' "animation" keys and their errors, and glTF node animations read
// through assimp, against the same transforms written as still files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "softraster/error.h"
#include "softraster/scene/animation.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene.h"
#include "test_support.h"

using namespace softraster;

namespace {

Track<glm::dvec3> track(std::vector<double> times, std::vector<double> xs) {
    Track<glm::dvec3> t;
    t.times = std::move(times);
    for (double x : xs) t.values.push_back(glm::dvec3(x, -x, 0.0));
    return t;
}

double x_at(const Track<glm::dvec3>& t, Interpolation how, double time) { return sample(t, how, time).x; }

bool same_bits(const glm::mat4& a, const glm::mat4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::filesystem::path write(const std::string& name, const std::string& text) {
    return test::write_temp_file("softraster_animation_tests", name, text);
}

const char* kScene = R"({"version": 2, "image": {"width": 32, "height": 16},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]CAMERA},
  "objects": [{"builtin": {"type": "cube"}, "transform": {"translate": [1, 2, 3], "rotate": [10, 20, 30], "scale": 2}OBJECT}]})";

std::string scene_text(const std::string& object, const std::string& camera = "") {
    std::string s = kScene;
    s.replace(s.find("CAMERA"), 6, camera);
    s.replace(s.find("OBJECT"), 6, object);
    return s;
}

std::string error_of(const std::string& text) {
    return test::error_of([&] { load_scene(write("bad.json", text)); });
}

}  // namespace

TEST(Animation, LinearAndStepBetweenKeysHoldOutside) {
    const auto t = track({1.0, 3.0, 4.0}, {10.0, 20.0, -20.0});
    EXPECT_EQ(x_at(t, Interpolation::Linear, 0.0), 10.0);  // before the first key
    EXPECT_EQ(x_at(t, Interpolation::Linear, 1.0), 10.0);
    EXPECT_EQ(x_at(t, Interpolation::Linear, 2.5), 17.5);
    EXPECT_EQ(x_at(t, Interpolation::Linear, 3.0), 20.0);
    EXPECT_EQ(x_at(t, Interpolation::Linear, 3.25), 10.0);
    EXPECT_EQ(x_at(t, Interpolation::Linear, 9.0), -20.0);  // after the last
    EXPECT_EQ(x_at(t, Interpolation::Step, 2.99), 10.0);
    EXPECT_EQ(x_at(t, Interpolation::Step, 3.0), 20.0);
    EXPECT_EQ(x_at(t, Interpolation::Step, 3.99), 20.0);
    EXPECT_EQ(sample(t, Interpolation::Linear, 2.5).y, -17.5);  // every component
    const auto one = track({2.0}, {5.0});
    for (double time : {0.0, 2.0, 7.0}) EXPECT_EQ(x_at(one, Interpolation::Smooth, time), 5.0);
}

TEST(Animation, SmoothIsHermiteWithNeighbourSlopes) {
    // Two keys: both slopes zero, so smoothstep: 3s^2 - 2s^3 of the way.
    const auto two = track({0.0, 2.0}, {0.0, 8.0});
    EXPECT_DOUBLE_EQ(x_at(two, Interpolation::Smooth, 0.5), 8.0 * (3 * 0.0625 - 2 * 0.015625));
    EXPECT_DOUBLE_EQ(x_at(two, Interpolation::Smooth, 1.0), 4.0);
    // Values 0, 2, 4 at 0, 1, 2 s: slopes 0, (4 - 0) / (2 - 0) = 2, 0. On [0, 1] at s = 0.5:
    // h00 0 + h10 h 0 + h01 2 + h11 h 2, with h01 = 0.5 and h11 = 0.125 - 0.25.
    const auto three = track({0.0, 1.0, 2.0}, {0.0, 2.0, 4.0});
    EXPECT_DOUBLE_EQ(x_at(three, Interpolation::Smooth, 0.5), 0.5 * 2.0 + (0.125 - 0.25) * 2.0);
    // The curve's slope is continuous through the middle key, and equals 2 there.
    const double e = 1e-6;
    const double left = (x_at(three, Interpolation::Smooth, 1.0) - x_at(three, Interpolation::Smooth, 1.0 - e)) / e;
    const double right = (x_at(three, Interpolation::Smooth, 1.0 + e) - x_at(three, Interpolation::Smooth, 1.0)) / e;
    EXPECT_NEAR(left, 2.0, 1e-4);
    EXPECT_NEAR(right, 2.0, 1e-4);
    // Uneven key spacing: slope per second (p2 - p0) / (t2 - t0), so the curve stays C1.
    const auto uneven = track({0.0, 1.0, 4.0}, {0.0, 1.0, 7.0});
    const double l = (x_at(uneven, Interpolation::Smooth, 1.0) - x_at(uneven, Interpolation::Smooth, 1.0 - e)) / e;
    const double r = (x_at(uneven, Interpolation::Smooth, 1.0 + e) - x_at(uneven, Interpolation::Smooth, 1.0)) / e;
    EXPECT_NEAR(l, 7.0 / 4.0, 1e-4);
    EXPECT_NEAR(r, 7.0 / 4.0, 1e-4);
}

TEST(Animation, QuaternionsSlerpTheShortWay) {
    Track<glm::dquat> t;
    t.times = {0.0, 1.0};
    const glm::dquat a(1, 0, 0, 0), b = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    t.values = {a, -b};  // -b is the same rotation as b: the way from a to it is 90 degrees, not 270
    const glm::dquat half = sample(t, Interpolation::Linear, 0.5);
    const glm::dvec3 turned = glm::mat3_cast(half) * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(turned.x, std::cos(glm::radians(45.0)), 1e-12);
    EXPECT_NEAR(turned.z, -std::sin(glm::radians(45.0)), 1e-12);
    EXPECT_EQ(sample(t, Interpolation::Step, 0.9), a);
}

TEST(Animation, SceneKeysGiveTheModelMatrixOfTheirValues) {
    const Scene s = load_scene(write("keys.json", scene_text(R"(, "animation": {"keys": [
        {"time": 0, "translate": [0, 0, 0]}, {"time": 2, "translate": [4, 0, -2], "rotate": [0, 90, 0]},
        {"time": 4, "rotate": [0, 180, 0], "scale": 3}]})")));
    ASSERT_TRUE(s.objects[0].motion);
    EXPECT_DOUBLE_EQ(animation_length(s), 4.0);
    // Where no key gives a property, the transform's value; each property's own keys.
    // t = 1: translate halfway (2, 0, -1); rotate from its one key... rotate keys at 2 and
    // 4 only, so before 2 it holds (0, 90, 0); scale keys at 4 only: 3 throughout.
    EXPECT_TRUE(same_bits(scene_at(s, 1.0).objects[0].model, model_matrix({2, 0, -1}, {0, 90, 0}, glm::vec3(3))));
    EXPECT_TRUE(same_bits(scene_at(s, 3.0).objects[0].model, model_matrix({4, 0, -2}, {0, 135, 0}, glm::vec3(3))));
    EXPECT_TRUE(same_bits(scene_at(s, 9.0).objects[0].model, model_matrix({4, 0, -2}, {0, 180, 0}, glm::vec3(3))));
    // A rotation no key gives keeps the transform's, product for product.
    const Scene t = load_scene(write("translate_only.json", scene_text(R"(, "animation": {"keys": [{"time": 1, "translate": [1, 2, 3]}]})")));
    EXPECT_TRUE(same_bits(scene_at(t, 0.0).objects[0].model, t.objects[0].model));
    EXPECT_FALSE(scene_at(t, 0.0).objects[0].motion);
}

TEST(Animation, CameraKeys) {
    const Scene s = load_scene(write("camera.json", scene_text("", R"(, "animation": {"interpolation": "step", "keys": [
        {"time": 0, "eye": [0, 0, 3]}, {"time": 1, "eye": [3, 0, 0], "target": [0, 1, 0]}]})")));
    ASSERT_TRUE(s.camera_motion);
    EXPECT_DOUBLE_EQ(animation_length(s), 1.0);
    EXPECT_EQ(scene_at(s, 0.5).camera.eye, glm::vec3(0, 0, 3));
    EXPECT_EQ(scene_at(s, 0.5).camera.target, glm::vec3(0, 1, 0));  // a track of one key holds it
    EXPECT_EQ(scene_at(s, 1.0).camera.eye, glm::vec3(3, 0, 0));
}

TEST(Animation, ScenesWithoutKeysComeBackAsTheyAre) {
    const Scene s = load_scene(write("still.json", scene_text("")));
    EXPECT_EQ(animation_length(s), 0.0);
    EXPECT_TRUE(same_bits(scene_at(s, 5.0).objects[0].model, s.objects[0].model));
}

TEST(Animation, ErrorsNameTheKey) {
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"keys": []})")).find("objects[0].animation.keys: needs at least one key"), std::string::npos);
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"keys": [{"time": 1, "translate": [0, 0, 0]}, {"time": 1, "scale": 2}]})"))
                  .find("keys[1].time: key times must increase"),
              std::string::npos);
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"keys": [{"time": 1}]})")).find("keys[0]: a key needs at least one of"), std::string::npos);
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"keys": [{"time": -1, "scale": 1}]})")).find("keys[0].time: value -1 out of range"),
              std::string::npos);
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"keys": [{"time": 0, "scale": [1, 0, 1]}]})")).find("scale must not be zero"),
              std::string::npos);
    EXPECT_NE(error_of(scene_text(R"(, "animation": {"interpolation": "cubic", "keys": [{"time": 0, "scale": 1}]})")).find("unknown value 'cubic'"),
              std::string::npos);
    EXPECT_NE(error_of(scene_text("", R"(, "animation": {"keys": [{"time": 0, "eye": [0, 0, 0]}]})")).find("camera.animation.keys[0]: eye and target are the same point"),
              std::string::npos);
    std::string v1 = scene_text(R"(, "animation": {"keys": [{"time": 0, "scale": 1}]})");
    v1.replace(v1.find("\"version\": 2"), 12, "\"version\": 1");
    EXPECT_NE(error_of(v1).find("a version 2 key in a version 1 file"), std::string::npos);
}

// A glTF file with one triangle under a parent node: the parent's translation and the
// child's rotation move over [0, 2] s, the child also has a fixed translation. Times and
// values are exact in float.
namespace {

std::string base64(const std::string& bytes) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) n |= uint8_t(bytes[i + 2]);
        out += abc[(n >> 18) & 63];
        out += abc[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? abc[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? abc[n & 63] : '=';
    }
    return out;
}

template <class... F>
std::string floats(F... f) {
    const float values[] = {float(f)...};
    return std::string(reinterpret_cast<const char*>(values), sizeof values);
}

std::string animated_gltf(const std::string& interpolation) {
    const std::string positions = floats(0, 0, 0, 1, 0, 0, 0, 1, 0);
    const std::string times = floats(0, 2);
    const std::string moves = floats(0, 0, 0, 4, 0, 0);
    const double h = std::sqrt(0.5);
    const std::string turns = floats(0, 0, 0, 1, 0, h, 0, h);  // identity, then 90 degrees about y (x, y, z, w)
    const std::string buffer = positions + times + moves + turns;
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"name": "parent", "translation": [0, 1, 0], "children": [1]},
                {"name": "child", "mesh": 0, "translation": [0, 0, -1]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "animations": [{"samplers": [{"input": 1, "output": 2, "interpolation": ")" + interpolation + R"("},
                                   {"input": 1, "output": 3, "interpolation": ")" + interpolation + R"("}],
                      "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                   {"sampler": 1, "target": {"node": 1, "path": "rotation"}}]}],
      "buffers": [{"byteLength": )" + std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + base64(buffer) + R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                      {"buffer": 0, "byteOffset": 44, "byteLength": 24}, {"buffer": 0, "byteOffset": 68, "byteLength": 32}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [2]},
                    {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC3"},
                    {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC4"}]})";
}

}  // namespace

TEST(Animation, GltfNodeAnimationsMoveTheirNodesAndChildren) {
    const Model m = load_model(write("animated.gltf", animated_gltf("LINEAR")));
    ASSERT_EQ(m.objects.size(), 1u);
    ASSERT_TRUE(m.objects[0].motion);
    EXPECT_NEAR(m.objects[0].motion->end(), 2.0, 1e-9);
    // World = T(parent's translation at t) * T(0, 0, -1) * R(child's rotation at t).
    auto expected = [](double x, double degrees) {
        return glm::translate(glm::dmat4(1.0), glm::dvec3(x, 0, 0)) * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -1)) *
               glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0, 1, 0));
    };
    for (double t : {0.0, 0.5, 1.0, 2.0, 3.0}) {
        const glm::mat4 got = m.objects[0].motion->model(t);
        const glm::dmat4 want = expected(2.0 * std::min(t, 2.0), 45.0 * std::min(t, 2.0));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], want[c][r], 1e-6) << "t " << t << " [" << c << "][" << r << "]";
    }
    // At rest (no time asked for) the file's own transforms.
    EXPECT_NEAR(m.objects[0].model[3][1], 1.0f, 1e-6);
    EXPECT_TRUE(m.ignored.empty());
}
