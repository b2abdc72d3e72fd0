#include "cli/model_options.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "softraster/error.h"

namespace softraster::cli {
namespace {

constexpr int kMaxSide = 16384;

// "W" or "WxH", each side in [1, 16384].
void parse_size(const std::string& text, int& w, int& h) {
    const size_t x = text.find('x');
    auto side = [&](const std::string& part) {
        char* end = nullptr;
        const long v = part.empty() ? 0 : std::strtol(part.c_str(), &end, 10);
        if (part.empty() || *end != '\0' || v < 1 || v > kMaxSide)
            throw InputError("--size " + text + ": expected W or WxH, each from 1 to " + std::to_string(kMaxSide));
        return int(v);
    };
    w = side(text.substr(0, x));
    h = x == std::string::npos ? w : side(text.substr(x + 1));
}

// "R,G,B[,A]" with components in [0, 1], or "#RRGGBB[AA]".
glm::vec4 parse_color(const std::string& text) {
    const std::string bad = "--background " + text + ": expected R,G,B[,A] (each 0 to 1) or #RRGGBB[AA]";
    glm::vec4 c(0, 0, 0, 1);
    if (!text.empty() && text[0] == '#') {
        const std::string hex = text.substr(1);
        if ((hex.size() != 6 && hex.size() != 8) || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
            throw InputError(bad);
        for (size_t i = 0; i < hex.size() / 2; ++i) c[int(i)] = float(std::stoi(hex.substr(2 * i, 2), nullptr, 16)) / 255.0f;
        return c;
    }
    std::vector<std::string> parts(1);
    for (char ch : text) {
        if (ch == ',') parts.emplace_back();
        else parts.back() += ch;
    }
    if (parts.size() != 3 && parts.size() != 4) throw InputError(bad);
    for (size_t i = 0; i < parts.size(); ++i) {
        char* end = nullptr;
        const float v = parts[i].empty() ? -1.0f : std::strtof(parts[i].c_str(), &end);
        if (parts[i].empty() || *end != '\0' || !(v >= 0.0f && v <= 1.0f)) throw InputError(bad);
        c[int(i)] = v;
    }
    return c;
}

const std::map<std::string, ModelView> kViews = {
    {"three-quarter", ModelView::ThreeQuarter}, {"front", ModelView::Front}, {"back", ModelView::Back},
    {"left", ModelView::Left}, {"right", ModelView::Right}, {"top", ModelView::Top},
    {"bottom", ModelView::Bottom}, {"iso", ModelView::Iso}};
const std::map<std::string, Shading> kShadings = {
    {"unlit", Shading::Unlit}, {"flat", Shading::Flat}, {"gouraud", Shading::Gouraud}, {"lambert", Shading::Lambert},
    {"blinn_phong", Shading::BlinnPhong}, {"phong", Shading::Phong}, {"pbr", Shading::Pbr}, {"normals", Shading::Normals}, {"depth", Shading::Depth}};

}  // namespace

void add_model_options(CLI::App& cmd, ModelOptions& opt, int default_size) {
    cmd.add_option("--size", opt.size, "Picture size W or WxH (default " + std::to_string(default_size) + ")");
    cmd.add_option("--view", opt.view, "Side the model is seen from")
        ->check(CLI::IsMember({"three-quarter", "front", "back", "left", "right", "top", "bottom", "iso"}))
        ->capture_default_str();
    cmd.add_option("--background", opt.background, "Background R,G,B[,A] (0 to 1) or #RRGGBB[AA] (default 0.2,0.2,0.25)");
    cmd.add_option("--samples", opt.samples, "MSAA samples per pixel: 1, 2, 4, 8 or 16")
        ->check(CLI::IsMember({1, 2, 4, 8, 16}))
        ->capture_default_str();
    cmd.add_option("--shading", opt.shading, "Shading for every material (default: lambert, or unlit where the file says)")
        ->check(CLI::IsMember({"unlit", "flat", "gouraud", "lambert", "blinn_phong", "phong", "pbr", "normals", "depth"}));
    cmd.add_option("--camera", opt.camera, "Look through the file's camera N (0 is the first) instead of framing the model")
        ->check(CLI::Range(0, 1 << 20));
    cmd.add_option("--color-space", opt.color_space,
                   "srgb: color textures decoded, light added and blended linearly, the picture encoded (as glTF intends); "
                   "linear: every value used as stored")
        ->check(CLI::IsMember({"srgb", "linear"}))
        ->capture_default_str();
    cmd.add_option("--tone-mapping", opt.tone_mapping, "Tone curve for bright light: none, reinhard or aces")
        ->check(CLI::IsMember({"none", "reinhard", "aces"}))
        ->capture_default_str();
    cmd.add_option("--exposure", opt.exposure, "Light multiplied by this before the tone curve")
        ->check(CLI::Range(1e-6, 1e6))
        ->capture_default_str();
    cmd.add_flag("--shadows", opt.shadows,
                 "Shadow maps for the key light, or the file's lights (at most 4)");
    cmd.add_flag("--ssao", opt.ambient_occlusion, "Screen-space ambient occlusion: creases and contacts darken (radius a tenth of the model's)");
    cmd.add_option("--anisotropy", opt.anisotropy, "Anisotropic filtering: up to this many texture lookups along a stretched footprint (1 to 16)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    cmd.add_option("--env", opt.env, "An equirectangular .hdr or .exr picture that lights pbr materials (image-based lighting)");
    cmd.add_option("--env-intensity", opt.env_intensity, "The environment's light multiplied by this")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    cmd.add_flag("--env-background", opt.env_background, "Show the --env picture behind the model instead of --background");
    cmd.add_flag("-v,--verbose", opt.verbose, "Also say what the file has that is not drawn");
}

ModelPicture ModelOptions::picture(int default_size) const {
    ModelPicture p;
    p.width = p.height = default_size;
    if (!size.empty()) parse_size(size, p.width, p.height);
    p.color_space = color_space == "srgb" ? ColorSpace::Srgb : ColorSpace::Linear;
    if (!background.empty()) p.background = parse_color(background);
    p.tone_mapping.curve = tone_mapping == "reinhard" ? ToneCurve::Reinhard : tone_mapping == "aces" ? ToneCurve::Aces : ToneCurve::None;
    p.tone_mapping.exposure = exposure;
    p.samples = samples;
    p.view = kViews.at(view);
    if (!shading.empty()) p.shading = kShadings.at(shading);
    p.camera = camera;
    p.shadows = shadows;
    p.anisotropy = anisotropy;
    p.ambient_occlusion = ambient_occlusion;
    if (!env.empty()) p.environment = std::make_shared<const EnvironmentLighting>(prepare_environment(read_environment(env), env_intensity, env_background));
    return p;
}

Scene input_scene(const std::filesystem::path& path, const ModelOptions& options, const CLI::App& cmd) {
    if (path.extension() == ".json") {
        if (options.any_given(cmd))
            throw InputError(path.string() + ": --size, --view, --background, --samples, --shading and --camera are for model files; a scene file sets these itself");
        return load_scene(path);
    }
    const ModelPicture picture = options.picture(512);
    const Model model = load_model(path, MissingTexture::Warn, picture.color_space);
    for (const std::string& w : model.warnings) std::fprintf(stderr, "softraster: warning: %s\n", w.c_str());
    if (options.verbose)
        for (const std::string& what : model.ignored) std::fprintf(stderr, "%s: not drawn: %s\n", path.string().c_str(), what.c_str());
    return model_scene(model, picture);
}

bool ModelOptions::any_given(const CLI::App& cmd) const {
    for (const char* name : {"--size", "--view", "--background", "--samples", "--shading", "--camera", "--color-space", "--tone-mapping", "--exposure", "--shadows", "--anisotropy", "--ssao", "--env", "--env-intensity", "--env-background"})
        if (cmd.count(name) > 0) return true;
    return false;
}

}  // namespace softraster::cli
