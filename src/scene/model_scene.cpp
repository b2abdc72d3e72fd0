// A model in a scene of its own: framed by its bounding sphere and lit by a default rig.
#include <algorithm>
#include <cmath>
#include <random>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "softraster/error.h"
#include "softraster/scene/model.h"

namespace softraster {
namespace {

constexpr float kFovY = 30.0f;  // degrees: a long lens, little perspective distortion

struct ViewDirection {
    glm::vec3 to_eye;  // from the model's center toward the camera
    glm::vec3 up;
};

ViewDirection direction(ModelView view) {
    switch (view) {
        case ModelView::Front: return {{0, 0, 1}, {0, 1, 0}};
        case ModelView::Back: return {{0, 0, -1}, {0, 1, 0}};
        case ModelView::Left: return {{-1, 0, 0}, {0, 1, 0}};
        case ModelView::Right: return {{1, 0, 0}, {0, 1, 0}};
        case ModelView::Top: return {{0, 1, 0}, {0, 0, -1}};
        case ModelView::Bottom: return {{0, -1, 0}, {0, 0, 1}};
        case ModelView::Iso: return {glm::normalize(glm::vec3(1, 1, 1)), {0, 1, 0}};
        case ModelView::ThreeQuarter: break;
    }
    // 35 degrees to the right of the front, 25 degrees above it.
    const float az = glm::radians(35.0f), el = glm::radians(25.0f);
    return {{std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)}, {0, 1, 0}};
}

}  // namespace

Scene model_scene(const Model& model, const ModelPicture& picture) {
    Scene scene;
    scene.width = picture.width;
    scene.height = picture.height;
    scene.background = picture.background;
    if (picture.color_space == ColorSpace::Srgb)  // the light that is stored as the values asked for
        for (int k = 0; k < 3; ++k) scene.background[k] = srgb::decode_value(picture.background[k]);
    scene.samples = picture.samples;
    scene.color_space = picture.color_space;
    scene.tone_mapping = picture.tone_mapping;
    scene.environment = picture.environment;
    scene.objects = model.objects;
    for (SceneObject& o : scene.objects) {
        if (picture.shading) o.material.shading = *picture.shading;
        o.material.sampler.max_anisotropy = picture.anisotropy;
    }

    const BoundingSphere sphere = bounding_sphere(model.objects).value_or(BoundingSphere{});
    const float radius = sphere.radius > 0.0f ? sphere.radius : 1.0f;
    ViewDirection dir = direction(picture.view);
    if (picture.to_eye) {  // (up is +y, or -z looking straight down or up)
        dir.to_eye = glm::normalize(*picture.to_eye);
        dir.up = std::abs(dir.to_eye.y) > 0.999f ? glm::vec3(0, 0, dir.to_eye.y > 0 ? -1 : 1) : glm::vec3(0, 1, 0);
    }
    if (picture.ambient_occlusion) {
        AmbientOcclusionSettings ao;
        ao.radius = 0.1f * radius;
        scene.ambient_occlusion = ao;
    }
    Camera& cam = scene.camera;
    if (picture.camera >= 0) {
        if (size_t(picture.camera) >= model.cameras.size())
            throw InputError("--camera " + std::to_string(picture.camera) + ": the model has " +
                             std::to_string(model.cameras.size()) + " camera(s)");
        cam = model.cameras[size_t(picture.camera)];
    } else {
        // The sphere fills the narrower of the two fields of view: seen from distance d it
        // spans a half-angle asin(r / d), so d = r / sin(half field of view).
        const float aspect = float(picture.width) / float(picture.height);
        const float half_y = glm::radians(kFovY) / 2.0f;
        const float half = std::min(half_y, std::atan(std::tan(half_y) * aspect));
        const float distance = radius / std::sin(half);
        cam.fov_y = kFovY;
        cam.target = sphere.center;
        cam.eye = sphere.center + distance * dir.to_eye;
        cam.up = dir.up;
        cam.near = std::max(distance - 1.01f * radius, 1e-3f * distance);
        cam.far = distance + 1.01f * radius;
    }

    // The rig, in the camera's frame: right r, up u, forward f.
    const glm::vec3 f = glm::normalize(cam.target - cam.eye);
    const glm::vec3 r = glm::normalize(glm::cross(f, cam.up));
    const glm::vec3 u = glm::cross(r, f);
    // The default map, its bias a 200th of the model's radius (the format's 0.02 units suits
    // a model a few units across only).
    ShadowSettings shadow;
    shadow.bias = 0.005f * radius;
    if (!model.lights.directional.empty() || !model.lights.punctual.empty()) {
        scene.lights = model.lights;
        scene.lights.ambient = glm::vec3(0.1f);
        size_t shadowed = 0;
        for (DirectionalLight& l : scene.lights.directional)
            if (picture.shadows && shadowed < Lights::kMaxShadowed) l.shadow = shadow, ++shadowed;
        for (PunctualLight& l : scene.lights.punctual)
            if (picture.shadows && (!l.spot || l.outer_angle <= 80.0f) && shadowed < Lights::kMaxShadowed) l.shadow = shadow, ++shadowed;
        return scene;
    }
    scene.lights.ambient = glm::vec3(0.25f);
    scene.lights.directional = {
        {glm::normalize(f + 0.6f * r - 0.8f * u), glm::vec3(0.75f), {}},  // key: from the upper left
        {glm::normalize(0.5f * f - r), glm::vec3(0.3f), {}},            // fill: from the right
    };
    if (picture.shadows) scene.lights.directional[0].shadow = shadow;
    return scene;
}

std::optional<BoundingSphere> bounding_sphere(const std::vector<SceneObject>& objects) {
    // Only the vertices drawn count: a file's unused vertices can lie anywhere.
    auto each_vertex = [&](auto&& f) {
        for (const SceneObject& o : objects)
            for (uint32_t i : primitive_indices(*o.mesh, o.primitive))
                f(glm::vec3(o.model * glm::vec4(o.mesh->vertices[i].position, 1.0f)));
    };
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    each_vertex([&](const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    });
    if (!(lo.x <= hi.x)) return std::nullopt;
    BoundingSphere s;
    s.center = 0.5f * (lo + hi);
    float r2 = 0.0f;
    each_vertex([&](const glm::vec3& p) { r2 = std::max(r2, glm::dot(p - s.center, p - s.center)); });
    s.radius = std::sqrt(r2);
    return s;
}

std::vector<glm::vec3> view_directions(const std::string& layout, int count, unsigned seed) {
    std::vector<glm::vec3> dirs;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    for (int i = 0; i < count; ++i) {
        if (layout == "sphere") {  // a Fibonacci lattice: evenly spread, pole to pole
            const double y = 1.0 - 2.0 * (i + 0.5) / count, r = std::sqrt(1.0 - y * y), a = golden * i;
            dirs.emplace_back(float(r * std::sin(a)), float(y), float(r * std::cos(a)));
        } else if (layout == "ring") {  // around the vertical axis, 20 degrees above the horizon
            const double a = 2.0 * M_PI * i / count, el = 20.0 * M_PI / 180.0;
            dirs.emplace_back(float(std::sin(a) * std::cos(el)), float(std::sin(el)), float(std::cos(a) * std::cos(el)));
        } else if (layout == "random") {  // uniform on the sphere (normalized Gaussian vectors), the same for a seed
            glm::dvec3 v;
            do v = {normal(random), normal(random), normal(random)};
            while (glm::dot(v, v) < 1e-12);
            dirs.emplace_back(glm::vec3(glm::normalize(v)));
        } else {
            throw InputError("layout " + layout + ": expected sphere, ring or random");
        }
    }
    return dirs;
}

}  // namespace softraster
