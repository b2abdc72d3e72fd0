// The scene format (docs/scene-format.md), versions 1 and 2: JSON -> Scene, every rule checked
// (a version 1 file may not use a key version 2 added). Errors name the file and the JSON
// path: "scene.json: objects[2].material.shininess: ...".
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "io/read_file.h"
#include "io/text_parse.h"
#include "scene/animation_json.h"
#include "scene/json_node.h"
#include "scene/lights_json.h"
#include "scene/state_json.h"
#include "softraster/error.h"
#include "softraster/framebuffer.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/builtin_meshes.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene.h"

namespace softraster {
namespace {

using nlohmann::json;
using scene_json::Node;

AmbientOcclusionSettings read_ambient_occlusion(const Node& n) {
    n.expect_object({"radius", "intensity", "bias"});
    AmbientOcclusionSettings s;
    if (n.has("radius")) s.radius = float(n["radius"].number_in(0, 1e30, true, false, "0 < radius <= 1e30"));
    if (n.has("intensity")) s.intensity = float(n["intensity"].number_in(0, 1e6, false, false, "0 to 1e6"));
    if (n.has("bias")) s.bias = float(n["bias"].number_in(0, 1, false, true, "0 <= bias < 1"));
    return s;
}

struct Loader {
    std::filesystem::path dir;
    std::string file;
    int version = 1;
    int samples = 1;
    ColorSpace color_space = ColorSpace::Linear;  // the picture's, and the color textures'
    std::map<std::string, std::shared_ptr<const Mesh>> meshes;  // one load per distinct file
    // One mesh per distinct builtin (its type and numbers): objects naming the same one share
    // it, as objects naming the same file do, so a scene of thousands of such objects holds
    // and draws from one copy of its vertices and indices, not thousands.
    std::map<std::string, std::shared_ptr<const Mesh>> builtins;
    std::map<std::string, std::shared_ptr<const Model>> models;
    std::map<std::pair<std::string, ColorSpace>, std::shared_ptr<const Texture>> textures;

    void read_image(const Node& n, Scene& s) {
        n.expect_object({"width", "height", "background", "samples"},
                        {"supersample", "clear_stencil", "color_space", "tone_mapping", "exposure"}, version);
        s.width = n["width"].integer_in(1, 16384);
        s.height = n["height"].integer_in(1, 16384);
        if (n.has("background")) s.background = n["background"].vec4();
        if (n.has("samples")) {
            s.samples = n["samples"].integer_in(1, 16);
            if (version < 2 && s.samples != 1 && s.samples != 4) n["samples"].fail("must be 1 or 4 (2, 8 and 16 need version 2)");
            if (!Framebuffer::valid_samples(s.samples)) n["samples"].fail("must be 1, 2, 4, 8 or 16");
        }
        samples = s.samples;
        if (n.has("supersample")) {
            s.supersample = n["supersample"].integer_in(1, 4);
            if (int64_t(s.width) * s.supersample > 16384 || int64_t(s.height) * s.supersample > 16384)
                n["supersample"].fail("the supersampled picture would exceed 16384 pixels in a direction");
        }
        if (n.has("clear_stencil")) s.clear_stencil = uint8_t(n["clear_stencil"].integer_in(0, 255));
        if (n.has("color_space"))
            s.color_space = n["color_space"].choice<ColorSpace>({{"linear", ColorSpace::Linear}, {"srgb", ColorSpace::Srgb}});
        color_space = s.color_space;
        if (n.has("tone_mapping"))
            s.tone_mapping.curve = n["tone_mapping"].choice<ToneCurve>(
                {{"none", ToneCurve::None}, {"reinhard", ToneCurve::Reinhard}, {"aces", ToneCurve::Aces}});
        if (n.has("exposure")) s.tone_mapping.exposure = float(n["exposure"].number_in(0, 1e6, true, false, "0 < exposure <= 1e6"));
    }

    void read_camera(const Node& n, Scene& s) {
        Camera& c = s.camera;
        n.expect_object({"projection", "eye", "target", "up", "fov_y", "height", "near", "far"}, {"animation"}, version);
        if (n.has("projection"))
            c.orthographic = n["projection"].choice<bool>({{"perspective", false}, {"orthographic", true}});
        c.eye = n["eye"].vec3();
        c.target = n["target"].vec3();
        if (n.has("up")) c.up = n["up"].nonzero_vec3();
        if (n.has("fov_y")) c.fov_y = float(n["fov_y"].number_in(0, 180, true, true, "0 < fov_y < 180"));
        if (n.has("height")) c.height = float(n["height"].number_in(0, HUGE_VAL, true, false, "> 0"));
        if (n.has("near")) c.near = float(n["near"].number_in(0, HUGE_VAL, true, false, "> 0"));
        if (n.has("far")) c.far = float(n["far"].number_in(0, HUGE_VAL, true, false, "> 0"));
        if (!(c.near < c.far)) (n.has("far") ? n["far"] : n["near"]).fail("near must be less than far");
        const glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.eye);
        if (glm::length(view) == 0.0) n["target"].fail("eye and target are the same point");
        if (glm::length(glm::cross(glm::normalize(view), glm::normalize(glm::dvec3(c.up)))) < 1e-9)
            (n.has("up") ? n["up"] : n).fail("up is parallel to the view direction");
        if (n.has("animation")) s.camera_motion = scene_json::read_camera_animation(n["animation"], c);
    }

    std::shared_ptr<const Mesh> read_builtin(const Node& n) {
        if (!n.raw().is_object()) n.fail("expected an object");
        const std::string type = n["type"].string();
        auto positive = [&](const char* key, double def) {
            return n.has(key) ? n[key].number_in(0, HUGE_VAL, true, false, "> 0") : def;
        };
        auto count = [&](const char* key, int def, int min) {
            return n.has(key) ? n[key].integer_in(min, 1 << 14) : def;
        };
        // The mesh of make(numbers...), made for the first object that names this type with
        // these numbers (the key: each of them exactly, in hexadecimal).
        auto shared = [&](auto make, auto... numbers) {
            std::string key = type;
            char at[64];
            ((std::snprintf(at, sizeof at, " %a", double(numbers)), key += at), ...);
            auto& slot = builtins[key];
            if (!slot) slot = std::make_shared<Mesh>(make(numbers...));
            return slot;
        };
        if (type == "plane") {
            n.expect_object({"type", "size", "divisions"});
            return shared(make_plane, positive("size", 2), count("divisions", 1, 1));
        }
        if (type == "uv_sphere") {
            n.expect_object({"type", "radius", "rings", "segments"});
            return shared(make_uv_sphere, positive("radius", 1), count("rings", 32, 2), count("segments", 64, 3));
        }
        if (type == "torus") {
            n.expect_object({"type", "major", "minor", "rings", "segments"});
            return shared(make_torus, positive("major", 1), positive("minor", 0.25), count("rings", 48, 3), count("segments", 24, 3));
        }
        if (type == "cube") {
            n.expect_object({"type", "size"});
            return shared(make_cube, positive("size", 2));
        }
        n["type"].fail("unknown builtin '" + type + "' (expected one of: plane, uv_sphere, torus, cube)");
    }

    std::shared_ptr<const Mesh> read_mesh_file(const Node& n) {
        const std::string rel = n.string();
        if (rel.empty()) n.fail("empty mesh path");
        const std::string path = (dir / rel).lexically_normal().string();
        auto& slot = meshes[path];
        if (!slot) slot = std::make_shared<Mesh>(load_mesh(path));
        return slot;
    }

    // A color texture (base color, emissive) is sRGB-encoded in an sRGB scene; the other maps
    // hold data, never encoded.
    std::shared_ptr<const Texture> read_texture(const Node& n, bool color = false) {
        const std::string rel = n.string();
        if (rel.empty()) n.fail("empty texture path");
        const std::string path = (dir / rel).lexically_normal().string();
        const ColorSpace space = color ? color_space : ColorSpace::Linear;
        auto& slot = textures[{path, space}];
        if (!slot) {
            try {
                slot = std::make_shared<Texture>(softraster::read_image(path), space);
            } catch (const InputError& e) {
                n.fail(e.what());  // which key named the picture, then what is wrong with it
            }
        }
        return slot;
    }

    // Image-based lighting (docs/scene-format.md "Environment lighting").
    std::shared_ptr<const EnvironmentLighting> read_environment(const Node& n) {
        n.expect_object({"file", "intensity", "background"});
        const std::string rel = n["file"].string();
        if (rel.empty()) n["file"].fail("empty file path");
        const float intensity = n.has("intensity") ? float(n["intensity"].number_in(0, 1e6, false, false, "0 to 1e6")) : 1.0f;
        const bool background = n.has("background") && n["background"].boolean();
        try {
            return std::make_shared<const EnvironmentLighting>(
                prepare_environment(softraster::read_environment((dir / rel).lexically_normal()), intensity, background));
        } catch (const InputError& e) {
            n["file"].fail(e.what());
        }
    }

    // A value only version 2 knows, in a version 1 file: the same error as a v2 key.
    void need_v2(const Node& n, bool v2_value) const {
        if (v2_value && version < 2) n.fail("\"" + n.string() + "\" needs version 2 (set \"version\": 2)");
    }

    // The material's sampler state (docs/scene-format.md "Textures").
    void read_sampler(const Node& n, Sampler& s) {
        if (n.has("filter")) {
            const Node f = n["filter"];
            struct Choice { Filter mag, min; MipFilter mip; };
            const Choice c = f.choice<Choice>({{"nearest", {Filter::Nearest, Filter::Nearest, MipFilter::None}},
                                               {"bilinear", {Filter::Bilinear, Filter::Bilinear, MipFilter::None}},
                                               {"trilinear", {Filter::Bilinear, Filter::Bilinear, MipFilter::Linear}}});
            need_v2(f, c.mip != MipFilter::None);
            s.mag = c.mag, s.min = c.min, s.mip = c.mip;
        }
        if (n.has("min_filter")) {
            struct Choice { Filter min; MipFilter mip; };
            const Choice c = n["min_filter"].choice<Choice>({{"nearest", {Filter::Nearest, MipFilter::None}},
                                                             {"linear", {Filter::Bilinear, MipFilter::None}},
                                                             {"nearest_mipmap_nearest", {Filter::Nearest, MipFilter::Nearest}},
                                                             {"linear_mipmap_nearest", {Filter::Bilinear, MipFilter::Nearest}},
                                                             {"nearest_mipmap_linear", {Filter::Nearest, MipFilter::Linear}},
                                                             {"linear_mipmap_linear", {Filter::Bilinear, MipFilter::Linear}}});
            s.min = c.min, s.mip = c.mip;
        }
        if (n.has("mag_filter")) s.mag = n["mag_filter"].choice<Filter>({{"nearest", Filter::Nearest}, {"linear", Filter::Bilinear}});
        if (n.has("wrap")) {
            const Node w = n["wrap"];
            auto one = [&](const Node& e) {
                const Wrap r = e.choice<Wrap>({{"repeat", Wrap::Repeat}, {"clamp", Wrap::Clamp}, {"mirror", Wrap::Mirror}, {"border", Wrap::Border}});
                need_v2(e, r == Wrap::Mirror || r == Wrap::Border);
                return r;
            };
            if (w.raw().is_array()) {
                if (version < 2) w.fail("a wrap mode per axis needs version 2 (set \"version\": 2)");
                if (w.array_size() != 2) w.fail("expected one wrap mode or an array of 2 (s, t)");
                s.wrap_s = one(w.at(0)), s.wrap_t = one(w.at(1));
            } else {
                s.wrap_s = s.wrap_t = one(w);
            }
        }
        if (n.has("anisotropy")) s.max_anisotropy = n["anisotropy"].integer_in(1, 16);
        if (n.has("border_color")) {
            s.border = n["border_color"].vec4();
            for (int c = 0; c < 4; ++c)
                if (s.border[c] < 0.0f || s.border[c] > 1.0f) n["border_color"].fail("components must be in 0..1");
        }
    }

    void read_material(const Node& n, Material& m) {
        n.expect_object({"shading", "color", "texture", "filter", "wrap", "specular", "shininess", "blend"},
                        {"color_mask", "alpha_cutoff", "alpha_to_coverage", "interpolation", "min_filter", "mag_filter",
                         "border_color", "metallic", "roughness", "emissive", "occlusion_strength", "metallic_roughness_texture",
                         "occlusion_texture", "emissive_texture", "normal_texture", "normal_scale", "anisotropy"},
                        version);
        if (n.has("shading"))
            m.shading = n["shading"].choice<Shading>({{"unlit", Shading::Unlit}, {"flat", Shading::Flat},
                                                      {"gouraud", Shading::Gouraud}, {"lambert", Shading::Lambert},
                                                      {"blinn_phong", Shading::BlinnPhong}, {"phong", Shading::Phong}, {"pbr", Shading::Pbr},
                                                      {"normals", Shading::Normals}, {"depth", Shading::Depth}});
        if (n.has("shading")) need_v2(n["shading"], m.shading == Shading::Phong || m.shading == Shading::Pbr);
        if (n.has("color")) m.color = n["color"].vec4();
        read_sampler(n, m.sampler);
        if (n.has("specular")) m.specular = n["specular"].vec3();
        if (n.has("shininess")) m.shininess = float(n["shininess"].number_in(0, HUGE_VAL, false, false, ">= 0"));
        if (n.has("blend")) {
            const Node b = n["blend"];
            if (b.raw().is_object() && version >= 2) {
                m.blend = BlendMode::Custom;
                m.blend_equation = scene_json::read_blend_equation(b);
            } else {
                if (b.raw().is_object()) b.fail("a blend object needs version 2 (version 1 takes opaque, alpha or additive)");
                m.blend = b.choice<BlendMode>({{"opaque", BlendMode::Opaque}, {"alpha", BlendMode::Alpha}, {"additive", BlendMode::Additive}});
            }
        }
        if (n.has("color_mask")) {
            const Node c = n["color_mask"];
            if (c.array_size() != 4) c.fail("expected an array of 4 booleans (r, g, b, a)");
            m.color_mask = 0;
            for (size_t i = 0; i < 4; ++i) m.color_mask |= uint8_t(c.at(i).boolean() ? 1u << i : 0u);
        }
        if (n.has("alpha_cutoff")) m.alpha_cutoff = float(n["alpha_cutoff"].number_in(0, 1, false, false, "0..1"));
        if (n.has("alpha_to_coverage")) {
            m.alpha_to_coverage = n["alpha_to_coverage"].boolean();
            if (m.alpha_to_coverage && samples == 1) n["alpha_to_coverage"].fail("needs image.samples > 1");
        }
        if (n.has("interpolation"))
            m.affine = n["interpolation"].choice<bool>({{"perspective", false}, {"affine", true}});
        if (n.has("texture")) m.texture = read_texture(n["texture"], /*color=*/true);
        if (n.has("metallic")) m.metallic = float(n["metallic"].number_in(0, 1, false, false, "0..1"));
        if (n.has("roughness")) m.roughness = float(n["roughness"].number_in(0, 1, false, false, "0..1"));
        if (n.has("emissive")) {
            m.emissive = n["emissive"].vec3();
            if (!(m.emissive.x >= 0 && m.emissive.y >= 0 && m.emissive.z >= 0 && std::max({m.emissive.x, m.emissive.y, m.emissive.z}) <= 1e30f))
                n["emissive"].fail("components must be in 0..1e30");
        }
        if (n.has("occlusion_strength")) m.occlusion_strength = float(n["occlusion_strength"].number_in(0, 1, false, false, "0..1"));
        if (n.has("metallic_roughness_texture")) m.metallic_roughness_texture = read_texture(n["metallic_roughness_texture"]);
        if (n.has("occlusion_texture")) m.occlusion_texture = read_texture(n["occlusion_texture"]);
        if (n.has("emissive_texture")) m.emissive_texture = read_texture(n["emissive_texture"], /*color=*/true);
        if (n.has("normal_texture")) {
            if (m.shading != Shading::Pbr) n["normal_texture"].fail("a normal map needs shading 'pbr'");
            m.normal_texture = read_texture(n["normal_texture"]);
        }
        if (n.has("normal_scale")) m.normal_scale = float(n["normal_scale"].number_in(-1e6, 1e6, false, false, "-1e6..1e6"));
    }

    // A model file (version 2): every object it places, each under the object's transform,
    // with the file's own materials; the object may set the shading, culling, winding and
    // per-fragment state of all of them.
    void read_model_object(const Node& n, const SceneObject& o, std::vector<SceneObject>& out) {
        for (const char* key : {"primitive", "line_width", "point_size", "wireframe"})
            if (n.has(key)) n[key].fail("not with 'model' (the file says what it draws)");
        std::optional<Shading> shading;
        if (n.has("material")) {
            const Node m = n["material"];
            m.expect_object({"shading"});
            Material with;
            read_material(m, with);
            shading = with.shading;
        }
        const std::string rel = n["model"].string();
        if (rel.empty()) n["model"].fail("empty model path");
        const std::string path = (dir / rel).string();
        auto& slot = models[path];
        if (!slot) slot = std::make_shared<Model>(load_model(path, MissingTexture::Fail, color_space));
        for (const SceneObject& part : slot->objects) {
            SceneObject placed = part;
            placed.model = o.model * part.model;
            if (o.motion || part.motion) {  // the object's links, then the part's own
                auto motion = std::make_shared<ObjectMotion>();
                motion->links = o.motion ? o.motion->links : std::vector<MotionLink>{{glm::dmat4(o.model), nullptr}};
                if (part.motion) motion->links.insert(motion->links.end(), part.motion->links.begin(), part.motion->links.end());
                else motion->links.push_back({glm::dmat4(part.model), nullptr});
                placed.motion = std::move(motion);
            }
            if (shading && (part.primitive == Topology::Triangles)) placed.material.shading = *shading;
            if (n.has("cull")) placed.cull = o.cull;
            if (n.has("front_face")) placed.front_face = o.front_face;
            placed.state = o.state;
            out.push_back(std::move(placed));
        }
    }

    void read_object(const Node& n, std::vector<SceneObject>& out) {
        n.expect_object({"mesh", "builtin", "transform", "material", "cull", "front_face"},
                        {"depth", "stencil", "scissor", "primitive", "line_width", "point_size", "wireframe", "model", "animation"},
                        version);
        SceneObject o;
        if (int(n.has("mesh")) + int(n.has("builtin")) + int(n.has("model")) != 1)
            n.fail(version >= 2 ? "exactly one of 'mesh', 'builtin' and 'model' is required"
                                : "exactly one of 'mesh' and 'builtin' is required");
        glm::vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
        if (n.has("transform")) {
            const Node t = n["transform"];
            t.expect_object({"translate", "rotate", "scale"});
            if (t.has("translate")) translate = t["translate"].vec3();
            if (t.has("rotate")) rotate = t["rotate"].vec3();
            if (t.has("scale")) {
                const Node s = t["scale"];
                scale = s.raw().is_array() ? s.vec3() : glm::vec3(float(s.number()));
                if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) s.fail("scale must not be zero");
            }
        }
        o.model = model_matrix(translate, rotate, scale);
        if (n.has("animation")) o.motion = scene_json::read_object_animation(n["animation"], translate, rotate, scale);
        if (n.has("cull"))
            o.cull = n["cull"].choice<CullMode>({{"back", CullMode::Back}, {"front", CullMode::Front}, {"none", CullMode::None}});
        if (n.has("front_face")) o.front_face = n["front_face"].choice<FrontFace>({{"ccw", FrontFace::CCW}, {"cw", FrontFace::CW}});
        if (n.has("material") && !n.has("model")) read_material(n["material"], o.material);
        if (n.has("depth")) scene_json::read_depth(n["depth"], o.state);
        if (n.has("stencil")) scene_json::read_stencil(n["stencil"], o.state);
        if (n.has("scissor")) {
            const Node r = n["scissor"];
            if (r.array_size() != 4) r.fail("expected [x, y, width, height]");
            o.state.scissor = ScissorRect{r.at(0).integer_in(0, 16384), r.at(1).integer_in(0, 16384), r.at(2).integer_in(0, 16384),
                                          r.at(3).integer_in(0, 16384)};
        }
        if (n.has("primitive"))
            o.primitive = n["primitive"].choice<Topology>({{"triangles", Topology::Triangles}, {"lines", Topology::Lines}, {"points", Topology::Points}});
        if (n.has("line_width")) o.line_width = float(n["line_width"].number_in(1, 255, false, false, "1..255"));
        if (n.has("point_size")) o.point_size = float(n["point_size"].number_in(1, 255, false, false, "1..255"));
        if (n.has("wireframe")) {
            const Node w = n["wireframe"];
            if (o.primitive != Topology::Triangles) w.fail("a wireframe needs primitive 'triangles'");
            w.expect_object({"color", "width"});
            Wireframe wire;
            if (w.has("color")) wire.color = w["color"].vec3();
            if (w.has("width")) wire.width = float(w["width"].number_in(1, 255, false, false, "1..255"));
            o.wireframe = wire;
        }
        if (n.has("model")) return read_model_object(n, o, out);
        o.mesh = n.has("builtin") ? read_builtin(n["builtin"]) : read_mesh_file(n["mesh"]);
        out.push_back(std::move(o));
    }
};

}  // namespace

Scene load_scene(const std::filesystem::path& path) { return parse_scene(read_whole_file(path), path.parent_path(), path.string()); }

Scene parse_scene(const std::string& text, const std::filesystem::path& dir, const std::string& file) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::exception& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ..."
        // (or out_of_range.406 for a number too large for a double)
        std::string what = e.what();
        if (const size_t p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
        throw InputError(file + ": malformed JSON: " + what);
    }
    Loader loader;
    loader.dir = dir;
    loader.file = file;
    Scene scene;
    const Node top(root, "", file);
    if (!root.is_object()) top.fail("expected an object");
    loader.version = top["version"].integer_in(1, 2);
    top.expect_object({"version", "image", "camera", "lights", "objects"}, {"draw_order", "environment", "ambient_occlusion"}, loader.version);
    if (top.has("environment")) scene.environment = loader.read_environment(top["environment"]);
    if (top.has("ambient_occlusion")) scene.ambient_occlusion = read_ambient_occlusion(top["ambient_occlusion"]);
    if (top.has("draw_order")) scene.sorted = top["draw_order"].choice<bool>({{"sorted", true}, {"file", false}});
    loader.read_image(top["image"], scene);
    loader.read_camera(top["camera"], scene);
    if (top.has("lights")) scene_json::read_lights(top["lights"], scene.lights, loader.version);
    const Node objects = top["objects"];
    for (size_t i = 0; i < objects.array_size(); ++i) loader.read_object(objects.at(i), scene.objects);
    add_tangents(scene.objects);
    return scene;
}

}  // namespace softraster
