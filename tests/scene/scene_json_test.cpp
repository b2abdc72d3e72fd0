// Scene format version 1: defaults, validation errors with their JSON paths, transforms and
// the draw order of opaque and blended objects.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/scene.h"
#include "softraster/scene/scene_renderer.h"
#include "test_support.h"

using namespace softraster;

namespace {

std::filesystem::path write_scene(const std::string& name, const std::string& json) {
    return test::write_temp_file("softraster_scene_tests", name, json);
}

const char* kMinimal = R"({"version": 1, "image": {"width": 32, "height": 16},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]}, "objects": [{"builtin": {"type": "cube"}}]})";

std::string error_of(const std::string& json) {
    return test::error_of([&] { load_scene(write_scene("bad.json", json)); });
}

std::string with(const std::string& from, const std::string& to) {
    std::string s = kMinimal;
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
}

}  // namespace

TEST(SceneJson, Defaults) {
    const Scene s = load_scene(write_scene("min.json", kMinimal));
    EXPECT_EQ(s.samples, 1);
    EXPECT_EQ(s.background, glm::vec4(0, 0, 0, 1));
    EXPECT_FALSE(s.camera.orthographic);
    EXPECT_EQ(s.camera.up, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(s.camera.fov_y, 45);
    EXPECT_FLOAT_EQ(s.camera.near, 0.1f);
    EXPECT_FLOAT_EQ(s.camera.far, 100);
    EXPECT_EQ(s.lights.ambient, glm::vec3(0));
    ASSERT_EQ(s.objects.size(), 1u);
    const SceneObject& o = s.objects[0];
    EXPECT_EQ(o.cull, CullMode::Back);
    EXPECT_EQ(o.front_face, FrontFace::CCW);
    EXPECT_EQ(o.material.shading, Shading::Lambert);
    EXPECT_EQ(o.material.sampler.mag, Filter::Bilinear);
    EXPECT_EQ(o.material.sampler.min, Filter::Bilinear);
    EXPECT_EQ(o.material.sampler.mip, MipFilter::None);
    EXPECT_EQ(o.material.sampler.wrap_s, Wrap::Repeat);
    EXPECT_EQ(o.material.sampler.wrap_t, Wrap::Repeat);
    EXPECT_EQ(o.material.sampler.max_anisotropy, 1);
    EXPECT_FLOAT_EQ(o.material.shininess, 32);
    EXPECT_EQ(o.material.blend, BlendMode::Opaque);
    EXPECT_EQ(o.mesh->triangle_count(), 12u);
}

TEST(SceneJson, Anisotropy) {
    std::string v2 = with("\"version\": 1", "\"version\": 2");
    const size_t at = v2.find("\"builtin\"");
    v2.insert(at, "\"material\": {\"filter\": \"trilinear\", \"anisotropy\": 8}, ");
    EXPECT_EQ(load_scene(write_scene("aniso.json", v2)).objects[0].material.sampler.max_anisotropy, 8);
}

TEST(SceneJson, AmbientOcclusion) {
    std::string v2 = with("\"version\": 1", "\"version\": 2");
    EXPECT_FALSE(load_scene(write_scene("no_ao.json", v2)).ambient_occlusion);
    v2.insert(v2.rfind('}'), ", \"ambient_occlusion\": {\"radius\": 0.25, \"bias\": 0}");
    const Scene s = load_scene(write_scene("ao.json", v2));
    ASSERT_TRUE(s.ambient_occlusion);
    EXPECT_EQ(s.ambient_occlusion->radius, 0.25f);
    EXPECT_EQ(s.ambient_occlusion->intensity, 2.0f);
    EXPECT_EQ(s.ambient_occlusion->bias, 0.0f);
}

TEST(SceneJson, ErrorsNameThePathAndTheProblem) {
    const std::pair<std::string, const char*> cases[] = {
        {with("\"width\": 32", "\"width\": 0"), "image.width: value 0 out of range"},
        {with("\"width\": 32", "\"width\": 20000"), "image.width: value 20000 out of range"},
        {with("\"width\": 32", "\"width\": \"32\""), "image.width: expected an integer, got string"},
        {with("\"height\": 16}", "\"height\": 16, \"samples\": 3}"), "image.samples: must be 1 or 4"},
        {with("\"target\": [0, 0, 0]", "\"target\": [0, 0, 0], \"near\": 5, \"far\": 2"), "camera.far: near must be less than far"},
        {with("\"target\": [0, 0, 0]", "\"target\": [0, 0, 0], \"fov_y\": 180"), "camera.fov_y: value 180 out of range"},
        {with("\"target\": [0, 0, 0]", "\"target\": [0, 0, 3]"), "eye and target are the same point"},
        {with("\"target\": [0, 0, 0]", "\"target\": [0, 0, 0], \"up\": [0, 0, 2]"), "camera.up: up is parallel"},
        {with("{\"builtin\": {\"type\": \"cube\"}}", "{\"builtin\": {\"type\": \"cube\"}, \"materal\": {}}"), "objects[0].materal: unknown key"},
        {with("{\"type\": \"cube\"}", "{\"type\": \"cube\", \"size\": -1}"), "objects[0].builtin.size: value -1 out of range"},
        {with("{\"type\": \"cube\"}", "{\"type\": \"cone\"}"), "objects[0].builtin.type: unknown builtin"},
        {with("{\"builtin\": {\"type\": \"cube\"}}", "{\"builtin\": {\"type\": \"cube\"}, \"material\": {\"shading\": \"toon\"}}"), "objects[0].material.shading: unknown value 'toon'"},
        {with("{\"builtin\": {\"type\": \"cube\"}}", "{\"builtin\": {\"type\": \"cube\"}, \"transform\": {\"scale\": [1, 0, 1]}}"), "objects[0].transform.scale: scale must not be zero"},
        {with("{\"builtin\": {\"type\": \"cube\"}}", "{}"), "objects[0]: exactly one of 'mesh' and 'builtin'"},
        {with("\"version\": 1", "\"version\": 3"), "version: value 3 out of range"},
        {with("\"version\": 1,", ""), "version: required field is missing"},
        {with("{\"builtin\": {\"type\": \"cube\"}}", "{\"mesh\": \"missing.obj\"}"), "missing.obj: file not found"},
        {"{\"version\": 1, \"image\": {", "malformed JSON"},
        {with("\"target\": [0, 0, 0]", "\"target\": [0, 0, 1e999]"), "malformed JSON"},
    };
    for (const auto& [json, expected] : cases) {
        const std::string err = error_of(json);
        EXPECT_NE(err.find(expected), std::string::npos) << "got: " << err << "\nwanted: " << expected;
        EXPECT_EQ(err.find('\n'), std::string::npos) << "one line: " << err;
    }
}

TEST(SceneJson, ModelMatrixScalesThenRotatesXYZThenTranslates) {
    const glm::mat4 m = model_matrix(glm::vec3(1, 2, 3), glm::vec3(90, 90, 0), glm::vec3(2));
    // (1, 0, 0) -> scale (2, 0, 0) -> Rx(90): (2, 0, 0) -> Ry(90): (0, 0, -2) -> translate.
    const glm::vec4 p = m * glm::vec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 1, 1e-5f);
    EXPECT_NEAR(p.y, 2, 1e-5f);
    EXPECT_NEAR(p.z, 1, 1e-5f);
    // (0, 1, 0) -> Rx(90): (0, 0, 1) -> Ry(90): (1, 0, 0).
    const glm::vec4 q = m * glm::vec4(0, 1, 0, 0);
    EXPECT_NEAR(q.x, 2, 1e-5f);
    EXPECT_NEAR(q.z, 0, 1e-5f);
}

TEST(SceneJson, BlendedObjectsAreDrawnLastFarthestFirst) {
    const std::string json = R"({"version": 1, "image": {"width": 8, "height": 8},
      "camera": {"eye": [0, 0, 10], "target": [0, 0, 0]},
      "objects": [
        {"builtin": {"type": "cube"}, "transform": {"translate": [0, 0, 2]}, "material": {"blend": "alpha"}},
        {"builtin": {"type": "cube"}, "transform": {"translate": [0, 0, -3]}, "material": {"blend": "additive"}},
        {"builtin": {"type": "plane"}, "transform": {"translate": [0, 0, 5]}},
        {"builtin": {"type": "cube"}, "transform": {"translate": [0, 0, 2]}, "material": {"blend": "alpha", "color": [1, 0, 0, 0.5]}}
      ]})";
    const Scene s = load_scene(write_scene("order.json", json));
    const SceneRenderer r(s);
    ASSERT_EQ(r.draws().size(), 4u);
    EXPECT_EQ(r.draws()[0].state.blend, BlendMode::Opaque);     // the plane
    EXPECT_EQ(r.draws()[1].state.blend, BlendMode::Additive);   // z = -3: farthest
    EXPECT_EQ(r.draws()[2].uniforms.color, glm::vec4(1));       // z = 2, file order kept on ties
    EXPECT_EQ(r.draws()[3].uniforms.color, glm::vec4(1, 0, 0, 0.5f));
    EXPECT_FALSE(r.draws()[1].state.depth_write);               // blended: test, no write
    EXPECT_TRUE(r.draws()[0].state.depth_write);
}

// Version 2 lines, points and wireframes become draws of the right primitive and state.
TEST(SceneJson, LinesPointsAndWireframes) {
    const std::string json = R"({"version": 2, "image": {"width": 8, "height": 8},
      "camera": {"eye": [0, 0, 10], "target": [0, 0, 0]},
      "objects": [
        {"builtin": {"type": "cube"}, "primitive": "lines", "line_width": 3, "material": {"shading": "lambert"}},
        {"builtin": {"type": "cube"}, "primitive": "points", "point_size": 4.5},
        {"builtin": {"type": "cube"}, "wireframe": {"color": [1, 0.5, 0], "width": 2}, "depth": {"offset": [2, 3]}}
      ]})";
    const Scene s = load_scene(write_scene("lines.json", json));
    EXPECT_EQ(s.objects[0].primitive, Topology::Lines);
    EXPECT_EQ(s.objects[2].primitive, Topology::Triangles);
    const SceneRenderer r(s);
    ASSERT_EQ(r.draws().size(), 4u);  // the wireframe is a draw of its own, right after its object
    const auto& lines = r.draws()[0];
    EXPECT_EQ(lines.primitive, Topology::Lines);
    EXPECT_EQ(lines.shading, Shading::Unlit);  // lines and points are unlit
    EXPECT_EQ(*lines.line_point_indices, triangle_edges(*s.objects[0].mesh));  // it has no line elements
    EXPECT_FLOAT_EQ(lines.state.line_width, 3);
    EXPECT_EQ(r.draws()[1].line_point_indices->size(), s.objects[1].mesh->vertices.size());
    EXPECT_FLOAT_EQ(r.draws()[1].state.point_size, 4.5f);
    const auto &surface = r.draws()[2], &wire = r.draws()[3];
    EXPECT_EQ(surface.primitive, Topology::Triangles);
    EXPECT_FLOAT_EQ(surface.state.polygon_offset_factor, 3);  // pushed back under its edges
    EXPECT_FLOAT_EQ(surface.state.polygon_offset_units, 4);
    EXPECT_EQ(wire.primitive, Topology::Lines);
    EXPECT_EQ(wire.uniforms.color, glm::vec4(1, 0.5f, 0, 1));
    EXPECT_EQ(wire.uniforms.texture, nullptr);
    EXPECT_FLOAT_EQ(wire.state.line_width, 2);
    EXPECT_EQ(r.triangle_count(), 12u);  // the surface only
}

// Version 2's color keys: the color space, the tone curve and the exposure; the color
// textures (texture, emissive_texture) take the scene's color space, the data maps never.
TEST(SceneJson, ColorSpaceAndToneMapping) {
    auto v2 = [](const std::string& json) {
        std::string s = json;
        return s.replace(s.find("\"version\": 1"), 12, "\"version\": 2");
    };
    const Scene plain = load_scene(write_scene("plain.json", v2(kMinimal)));
    EXPECT_EQ(plain.color_space, ColorSpace::Linear);
    EXPECT_FALSE(plain.tone_mapping.active());
    const std::string keys = "\"height\": 16, \"color_space\": \"srgb\", \"tone_mapping\": \"aces\", \"exposure\": 2.5}";
    const Scene s = load_scene(write_scene("color.json", v2(with("\"height\": 16}", keys))));
    EXPECT_EQ(s.color_space, ColorSpace::Srgb);
    EXPECT_EQ(s.tone_mapping.curve, ToneCurve::Aces);
    EXPECT_EQ(s.tone_mapping.exposure, 2.5f);
    EXPECT_TRUE(SceneRenderer(s, 1).make_framebuffer().srgb());
    // A framebuffer is reused (view) only where it fits: the same size, samples and color space.
    EXPECT_TRUE(SceneRenderer(s, 1).fits(SceneRenderer(s, 1).make_framebuffer()));
    EXPECT_FALSE(SceneRenderer(s, 1).fits(SceneRenderer(plain, 1).make_framebuffer()));  // linear
    Scene wider = s;
    wider.width += 2;
    EXPECT_FALSE(SceneRenderer(wider, 1).fits(SceneRenderer(s, 1).make_framebuffer()));
    Scene supersampled = s;
    supersampled.supersample = 2;
    EXPECT_FALSE(SceneRenderer(supersampled, 1).fits(SceneRenderer(s, 1).make_framebuffer()));

    const auto dir = test::write_temp_file("softraster_scene_tests", "tex.png", "").parent_path();
    Image img(2, 2);
    img.pixels.assign(4, Rgba8{255, 255, 255, 255});
    img.at(1, 0) = img.at(0, 1) = {0, 0, 0, 255};
    write_png(img, dir / "tex.png");
    const std::string textured = std::string(R"({"version": 2, "image": {"width": 8, "height": 8, "color_space": "srgb"},
      "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]}, "objects": [{"builtin": {"type": "cube"}, "material": {"shading": "pbr",
      "texture": "tex.png", "emissive_texture": "tex.png", "metallic_roughness_texture": "tex.png", "occlusion_texture": "tex.png"}}]})");
    const Scene t = load_scene(write_scene("textured.json", textured));
    const Material& m = t.objects[0].material;
    EXPECT_TRUE(m.texture->srgb());
    EXPECT_EQ(m.texture, m.emissive_texture);  // one texture per file and color space
    EXPECT_FALSE(m.metallic_roughness_texture->srgb());
    EXPECT_EQ(m.metallic_roughness_texture, m.occlusion_texture);
    EXPECT_EQ(m.texture->stored(1, 0, 0).r, 188);  // its mipmap averaged in linear light

    const std::pair<std::string, const char*> errors[] = {
        {with("\"height\": 16}", "\"height\": 16, \"color_space\": \"srgb\"}"), "image.color_space: a version 2 key in a version 1 file"},
        {with("\"height\": 16}", "\"height\": 16, \"exposure\": 2}"), "image.exposure"},
        {v2(with("\"height\": 16}", "\"height\": 16, \"color_space\": \"rec2020\"}")), "image.color_space: unknown value 'rec2020'"},
        {v2(with("\"height\": 16}", "\"height\": 16, \"tone_mapping\": \"filmic\"}")), "image.tone_mapping: unknown value 'filmic'"},
        {v2(with("\"height\": 16}", "\"height\": 16, \"exposure\": 0}")), "image.exposure: value 0 out of range"},
        {v2(with("\"height\": 16}", "\"height\": 16, \"exposure\": -1}")), "image.exposure: value -1 out of range"},
        {v2(with("\"height\": 16}", "\"height\": 16, \"exposure\": \"2\"}")), "image.exposure: expected a number"},
    };
    for (const auto& [json, expected] : errors) {
        const std::string err = error_of(json);
        EXPECT_NE(err.find(expected), std::string::npos) << "got: " << err << "\nwanted: " << expected;
    }
}

// Version 2's shadows: on directional and spot lights, their defaults and limits.
TEST(SceneJson, Shadows) {
    const std::string lights_at = "\"objects\"";
    auto with_lights = [&](const std::string& lights) {
        std::string s = kMinimal;
        s.replace(s.find("\"version\": 1"), 12, "\"version\": 2");
        return s.replace(s.find(lights_at), lights_at.size(), "\"lights\": " + lights + ", " + lights_at);
    };
    const Scene s = load_scene(write_scene("shadow.json", with_lights(R"({"directional": [{"direction": [0, -1, 0], "color": [1, 1, 1],
      "shadow": {}}, {"direction": [1, -1, 0], "color": [1, 1, 1]}], "spot": [{"position": [0, 3, 0], "direction": [0, -1, 0],
      "shadow": {"size": 64, "bias": 0.5, "slope_bias": 0, "pcf": 0}}]})")));
    ASSERT_TRUE(s.lights.directional[0].shadow.has_value());
    EXPECT_EQ(s.lights.directional[0].shadow->size, 1024);
    EXPECT_EQ(s.lights.directional[0].shadow->pcf, 1);
    EXPECT_FALSE(s.lights.directional[1].shadow.has_value());
    ASSERT_TRUE(s.lights.punctual[0].shadow.has_value());
    EXPECT_EQ(s.lights.punctual[0].shadow->size, 64);
    EXPECT_EQ(s.lights.punctual[0].shadow->bias, 0.5f);
    EXPECT_EQ(s.lights.punctual[0].shadow->slope_bias, 0.0f);
    // A point light's shadow (a cube map) has the same keys.
    const Scene point = load_scene(
        write_scene("point_shadow.json", with_lights(R"({"point": [{"position": [0, 1, 0], "shadow": {"size": 32}}]})")));
    ASSERT_TRUE(point.lights.punctual[0].shadow.has_value());
    EXPECT_FALSE(point.lights.punctual[0].spot);
    EXPECT_EQ(point.lights.punctual[0].shadow->size, 32);

    const std::string dir = R"({"direction": [0, -1, 0], "color": [1, 1, 1], "shadow": {}})";
    const std::pair<std::string, const char*> errors[] = {
        {with("\"objects\"", "\"lights\": {\"directional\": [" + dir + "]}, \"objects\""),
         "lights.directional[0].shadow: a version 2 key in a version 1 file"},
        {with_lights(R"({"point": [{"position": [0, 1, 0], "shadow": {"pcf": 5}}]})"), "lights.point[0].shadow.pcf: value 5 out of range"},
        {with_lights(R"({"spot": [{"position": [0, 1, 0], "direction": [0, -1, 0], "outer_angle": 85, "shadow": {}}]})"),
         "lights.spot[0].outer_angle: a spot light with a shadow has outer_angle at most 80"},
        {with_lights(R"({"directional": [{"direction": [0, -1, 0], "color": [1, 1, 1], "shadow": {"size": 8}}]})"),
         "lights.directional[0].shadow.size: value 8 out of range"},
        {with_lights(R"({"directional": [{"direction": [0, -1, 0], "color": [1, 1, 1], "shadow": {"pcf": 5}}]})"),
         "lights.directional[0].shadow.pcf: value 5 out of range"},
        {with_lights(R"({"directional": [{"direction": [0, -1, 0], "color": [1, 1, 1], "shadow": {"bias": -1}}]})"),
         "lights.directional[0].shadow.bias: value -1 out of range"},
        {with_lights(R"({"directional": [{"direction": [0, -1, 0], "color": [1, 1, 1], "shadow": {"softness": 1}}]})"),
         "lights.directional[0].shadow.softness: unknown key"},
        {with_lights("{\"directional\": [" + dir + "," + dir + "," + dir + "," + dir + "," + dir + "]}"),
         "lights.directional[4].shadow: at most 4 lights with a shadow"},
    };
    for (const auto& [json, expected] : errors) {
        const std::string err = error_of(json);
        EXPECT_NE(err.find(expected), std::string::npos) << "got: " << err << "\nwanted: " << expected;
    }
}

// Version 2's environment: the picture relative to the scene file, the intensity, the errors.
TEST(SceneJson, Environment) {
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int k = 0; k < 8; ++k) hdr += std::string("\x80\x80\x80\x81", 4);
    write_scene("env.hdr", hdr);
    write_scene("cut.hdr", hdr.substr(0, hdr.size() - 4));
    auto with_env = [](const std::string& env, int version = 2) {
        std::string s = kMinimal;
        s.replace(s.find("\"version\": 1"), 12, "\"version\": " + std::to_string(version));
        return s.replace(s.find("\"objects\""), 9, "\"environment\": " + env + ", \"objects\"");
    };
    const Scene s = load_scene(write_scene("env.json", with_env(R"({"file": "env.hdr", "intensity": 0.5})")));
    ASSERT_TRUE(s.environment);
    EXPECT_EQ(s.environment->intensity, 0.5f);
    EXPECT_NEAR(environment_irradiance(*s.environment, {0, 1, 0}).r, 1.0f, 1e-3f);
    const std::pair<std::string, const char*> errors[] = {
        {with_env(R"({"file": "env.hdr"})", 1), "environment: a version 2 key in a version 1 file"},
        {with_env(R"({"file": "missing.hdr"})"), "environment.file: "},
        {with_env(R"({"file": "cut.hdr"})"), "cut.hdr: corrupt Radiance HDR (truncated)"},
        {with_env(R"({"file": "env.hdr", "intensity": -1})"), "environment.intensity: value -1 out of range"},
        {with_env(R"({"file": "env.hdr", "rotation": 90})"), "environment.rotation: unknown key"},
        {with_env(R"({"intensity": 1})"), "environment.file: required field is missing"},
    };
    for (const auto& [json, expected] : errors) {
        const std::string err = error_of(json);
        EXPECT_NE(err.find(expected), std::string::npos) << "got: " << err << "\nwanted: " << expected;
    }
}

TEST(SceneJson, ObjectsNamingTheSameBuiltinShareItsMesh) {
    const Scene s = load_scene(write_scene("shared.json", R"({"version": 1, "image": {"width": 32, "height": 16},
      "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]}, "objects": [
        {"builtin": {"type": "uv_sphere", "radius": 0.5, "rings": 8, "segments": 16}},
        {"builtin": {"type": "uv_sphere", "segments": 16, "rings": 8, "radius": 0.5}, "transform": {"translate": [1, 0, 0]}},
        {"builtin": {"type": "uv_sphere", "radius": 0.5, "rings": 8, "segments": 17}},
        {"builtin": {"type": "uv_sphere", "radius": 0.5000001, "rings": 8, "segments": 16}},
        {"builtin": {"type": "torus", "rings": 8, "segments": 16}},
        {"builtin": {"type": "cube"}}, {"builtin": {"type": "cube", "size": 2}}, {"builtin": {"type": "cube", "size": 3}}]})"));
    ASSERT_EQ(s.objects.size(), 8u);
    EXPECT_EQ(s.objects[0].mesh.get(), s.objects[1].mesh.get());  // the same numbers, in any order
    EXPECT_NE(s.objects[0].mesh.get(), s.objects[2].mesh.get());
    EXPECT_NE(s.objects[0].mesh.get(), s.objects[3].mesh.get());  // (any difference counts)
    EXPECT_EQ(s.objects[2].mesh->triangle_count(), 2u * 8 * 17);
    EXPECT_EQ(s.objects[4].mesh->triangle_count(), 2u * 8 * 16);
    EXPECT_EQ(s.objects[5].mesh.get(), s.objects[6].mesh.get());  // the default size given or not
    EXPECT_NE(s.objects[5].mesh.get(), s.objects[7].mesh.get());
    EXPECT_EQ(s.objects[7].mesh->vertices.front().position, s.objects[5].mesh->vertices.front().position * 1.5f);
}
