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

// The value of `name` in `table`, or InputError naming the choices (the command line checks
// them before; the Python module's keyword arguments are checked here).
template <class T>
T choice(const std::map<std::string, T>& table, const std::string& what, const std::string& name) {
    if (const auto it = table.find(name); it != table.end()) return it->second;
    std::string names;
    for (const auto& [key, value] : table) names += (names.empty() ? "" : ", ") + key;
    throw InputError(what + " " + name + ": expected one of " + names);
}

}  // namespace


ModelPicture ModelOptions::picture(int default_size) const {
    ModelPicture p;
    p.width = p.height = default_size;
    if (!size.empty()) parse_size(size, p.width, p.height);
    p.color_space = color_space == "srgb" ? ColorSpace::Srgb : ColorSpace::Linear;
    if (!background.empty()) p.background = parse_color(background);
    p.tone_mapping.curve = tone_mapping == "reinhard" ? ToneCurve::Reinhard : tone_mapping == "aces" ? ToneCurve::Aces : ToneCurve::None;
    p.tone_mapping.exposure = exposure;
    p.samples = samples;
    p.view = choice(kViews, "view", view);
    if (!shading.empty()) p.shading = choice(kShadings, "shading", shading);
    p.camera = camera;
    p.shadows = shadows;
    p.anisotropy = anisotropy;
    p.ambient_occlusion = ambient_occlusion;
    if (!env.empty()) p.environment = std::make_shared<const EnvironmentLighting>(prepare_environment(read_environment(env), env_intensity, env_background));
    return p;
}

Scene input_scene(const std::filesystem::path& path, const ModelOptions& options) {
    if (path.extension() == ".json") {
        if (options.given)
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

}  // namespace softraster::cli
