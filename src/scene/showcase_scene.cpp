// The built-in showcase: one picture of what the renderer does, needing no files.
// Six shading models, a procedural texture, two transparent objects (alpha and additive),
// a ground plane that runs behind the camera (clipped at the near plane), and 4x MSAA.
#include <cmath>

#include "softraster/scene/builtin_meshes.h"
#include "softraster/scene/scene.h"

namespace softraster {
namespace {

// A two-tone checkerboard with a thin grid line, 512 x 512.
std::shared_ptr<const Texture> checker_texture() {
    constexpr int kSize = 512, kCell = 32;
    Image img(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool odd = ((x / kCell) + (y / kCell)) % 2 != 0;
            const bool line = x % kCell == 0 || y % kCell == 0;
            img.at(x, y) = line ? Rgba8{40, 40, 48, 255} : odd ? Rgba8{225, 222, 210, 255} : Rgba8{150, 160, 175, 255};
        }
    return std::make_shared<Texture>(img);
}

SceneObject object(std::shared_ptr<const Mesh> mesh, glm::vec3 translate, glm::vec3 rotate, Material m) {
    SceneObject o;
    o.mesh = std::move(mesh);
    o.model = model_matrix(translate, rotate, glm::vec3(1.0f));
    o.material = std::move(m);
    return o;
}

Material material(Shading s, glm::vec4 color) {
    Material m;
    m.shading = s;
    m.color = color;
    return m;
}

}  // namespace

Scene showcase_scene() {
    Scene s;
    s.width = 960;
    s.height = 540;
    s.samples = 4;
    s.background = {0.55f, 0.68f, 0.85f, 1.0f};
    s.camera.eye = {0.0f, 2.3f, 5.4f};
    s.camera.target = {0.0f, 0.3f, 0.0f};
    s.camera.fov_y = 50.0f;
    s.camera.near = 0.1f;
    s.camera.far = 100.0f;
    s.lights.ambient = {0.14f, 0.14f, 0.17f};
    s.lights.directional = {{{-0.5f, -0.9f, -0.6f}, {0.9f, 0.86f, 0.8f}, {}}, {{0.7f, -0.3f, 0.4f}, {0.25f, 0.3f, 0.42f}, {}}};

    const auto sphere = std::make_shared<Mesh>(make_uv_sphere(0.6, 32, 64));
    const auto coarse_sphere = std::make_shared<Mesh>(make_uv_sphere(0.6, 10, 16));
    const auto torus = std::make_shared<Mesh>(make_torus(0.5, 0.2, 48, 24));
    const auto cube = std::make_shared<Mesh>(make_cube(0.9));

    // Ground: 40 x 40, reaching far behind the eye, so the near plane clips it.
    Material ground = material(Shading::Lambert, glm::vec4(1.0f));
    ground.texture = checker_texture();
    ground.sampler.mip = MipFilter::Linear;  // trilinear: the far checkers fade to gray instead of shimmering
    s.objects.push_back(object(std::make_shared<Mesh>(make_plane(40.0, 8)), {0, 0, 0}, {0, 0, 0}, ground));

    Material shiny = material(Shading::BlinnPhong, {0.85f, 0.25f, 0.2f, 1.0f});
    shiny.specular = glm::vec3(0.7f);
    shiny.shininess = 48.0f;
    s.objects.push_back(object(torus, {-2.1f, 0.55f, -0.6f}, {60, 20, 0}, shiny));
    s.objects.push_back(object(coarse_sphere, {-0.75f, 0.6f, -1.2f}, {0, 0, 0}, material(Shading::Flat, {0.95f, 0.75f, 0.3f, 1})));
    s.objects.push_back(object(sphere, {0.6f, 0.6f, -1.4f}, {0, 0, 0}, material(Shading::Gouraud, {0.3f, 0.8f, 0.4f, 1})));
    Material crate = material(Shading::Lambert, glm::vec4(1.0f));
    crate.texture = ground.texture;
    crate.sampler = Sampler::plain(Filter::Nearest, Wrap::Repeat);
    s.objects.push_back(object(cube, {2.2f, 0.45f, -0.9f}, {0, 35, 0}, crate));
    s.objects.push_back(object(sphere, {-1.3f, 0.6f, 0.9f}, {0, 0, 0}, material(Shading::Normals, glm::vec4(1.0f))));

    // Transparent objects, drawn last, farthest first.
    Material glass = material(Shading::BlinnPhong, {0.3f, 0.5f, 1.0f, 0.45f});
    glass.specular = glm::vec3(0.8f);
    glass.blend = BlendMode::Alpha;
    s.objects.push_back(object(sphere, {0.25f, 0.65f, 0.6f}, {0, 0, 0}, glass));
    Material glow = material(Shading::Unlit, {1.0f, 0.55f, 0.15f, 0.6f});
    glow.blend = BlendMode::Additive;
    s.objects.push_back(object(torus, {1.5f, 0.35f, 1.3f}, {50, 0, 25}, glow));
    return s;
}

}  // namespace softraster
