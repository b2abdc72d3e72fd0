#include "scene/animation_json.h"

#include <string>

#include <glm/geometric.hpp>

namespace softraster::scene_json {

namespace {

constexpr size_t kMaxKeys = 100000;

Interpolation read_interpolation(const Node& n) {
    return n.choice<Interpolation>({{"step", Interpolation::Step}, {"linear", Interpolation::Linear}, {"smooth", Interpolation::Smooth}});
}

// {"interpolation", "keys": [{"time", ...}]}: checks the list and the times; `read_key`
// checks a key's other fields, reads them and says whether it found any.
template <class ReadKey>
Interpolation read_keys(const Node& n, const char* properties, ReadKey read_key) {
    n.expect_object({"keys", "interpolation"});
    const Interpolation how = n.has("interpolation") ? read_interpolation(n["interpolation"]) : Interpolation::Linear;
    const Node keys = n["keys"];
    const size_t count = keys.array_size();
    if (count == 0) keys.fail("needs at least one key");
    if (count > kMaxKeys) keys.fail("more than " + std::to_string(kMaxKeys) + " keys");
    double last = -1.0;
    for (size_t i = 0; i < count; ++i) {
        const Node key = keys.at(i);
        const double time = key["time"].number_in(0, 1e9, false, false, "0..1e9 seconds");
        if (i > 0 && !(time > last)) key["time"].fail("key times must increase from key to key");
        last = time;
        if (!read_key(key, time)) key.fail(std::string("a key needs at least one of: ") + properties);
    }
    return how;
}

template <class V>
void add_key(Track<V>& track, double time, const V& value) {
    track.times.push_back(time);
    track.values.push_back(value);
}

}  // namespace

std::shared_ptr<const ObjectMotion> read_object_animation(const Node& n, const glm::vec3& translate, const glm::vec3& rotate,
                                                          const glm::vec3& scale) {
    auto node = std::make_shared<NodeMotion>();
    node->interpolation = read_keys(n, "translate, rotate, scale", [&](const Node& key, double time) {
        key.expect_object({"time", "translate", "rotate", "scale"});
        if (key.has("translate")) add_key(node->translate, time, glm::dvec3(key["translate"].vec3()));
        if (key.has("rotate")) add_key(node->euler, time, glm::dvec3(key["rotate"].vec3()));
        if (key.has("scale")) {
            const Node s = key["scale"];
            const glm::vec3 v = s.raw().is_array() ? s.vec3() : glm::vec3(float(s.number()));
            if (v.x == 0.0f || v.y == 0.0f || v.z == 0.0f) s.fail("scale must not be zero");
            add_key(node->scale, time, glm::dvec3(v));
        }
        return key.has("translate") || key.has("rotate") || key.has("scale");
    });
    node->rest_translate = translate;
    node->rest_scale = scale;
    // A rotation no key gives is a track of one key, so that the matrix is model_matrix's,
    // product for product.
    if (node->euler.empty()) add_key(node->euler, 0.0, glm::dvec3(rotate));
    auto motion = std::make_shared<ObjectMotion>();
    motion->links.push_back({glm::dmat4(1.0), std::move(node)});
    return motion;
}

std::shared_ptr<const CameraMotion> read_camera_animation(const Node& n, const Camera& camera) {
    auto motion = std::make_shared<CameraMotion>();
    motion->interpolation = read_keys(n, "eye, target", [&](const Node& key, double time) {
        key.expect_object({"time", "eye", "target"});
        if (key.has("eye")) add_key(motion->eye, time, glm::dvec3(key["eye"].vec3()));
        if (key.has("target")) add_key(motion->target, time, glm::dvec3(key["target"].vec3()));
        return key.has("eye") || key.has("target");
    });
    // The view must be defined at every key (between keys it is the file's care).
    const Node keys = n["keys"];
    for (size_t i = 0; i < keys.array_size(); ++i) {
        const double time = keys.at(i)["time"].number();
        const glm::dvec3 eye = motion->eye.empty() ? glm::dvec3(camera.eye) : sample(motion->eye, motion->interpolation, time);
        const glm::dvec3 target = motion->target.empty() ? glm::dvec3(camera.target) : sample(motion->target, motion->interpolation, time);
        const glm::dvec3 view = target - eye;
        if (glm::length(view) == 0.0) keys.at(i).fail("eye and target are the same point");
        if (glm::length(glm::cross(glm::normalize(view), glm::normalize(glm::dvec3(camera.up)))) < 1e-9)
            keys.at(i).fail("up is parallel to the view direction");
    }
    return motion;
}

}  // namespace softraster::scene_json
