// The "lights" of scene files (docs/scene-format.md "Lights", "Shadows"), for scene_json.cpp.
#include "scene/lights_json.h"

#include <string>

namespace softraster::scene_json {
namespace {

// A light's shadow map (docs/scene-format.md "Shadows").
ShadowSettings read_shadow(const Node& n, const Lights& l) {
    n.expect_object({"size", "bias", "slope_bias", "pcf"});
    size_t shadowed = 1;
    for (const DirectionalLight& d : l.directional) shadowed += d.shadow.has_value();
    for (const PunctualLight& p : l.punctual) shadowed += p.shadow.has_value();
    if (shadowed > Lights::kMaxShadowed) n.fail("at most " + std::to_string(Lights::kMaxShadowed) + " lights with a shadow");
    ShadowSettings s;
    if (n.has("size")) s.size = n["size"].integer_in(16, 8192);
    if (n.has("bias")) s.bias = float(n["bias"].number_in(0, 1e30, false, false, "0 to 1e30"));
    if (n.has("slope_bias")) s.slope_bias = float(n["slope_bias"].number_in(0, 1e6, false, false, "0 to 1e6"));
    if (n.has("pcf")) s.pcf = n["pcf"].integer_in(0, 4);
    return s;
}

// A point or spot light (docs/scene-format.md "Lights").
PunctualLight read_punctual(const Node& d, bool spot, const Lights& lights) {
    if (spot) d.expect_object({"position", "direction", "color", "intensity", "range", "inner_angle", "outer_angle", "shadow"});
    else d.expect_object({"position", "color", "intensity", "range", "shadow"});
    PunctualLight light;
    light.spot = spot;
    light.position = d["position"].vec3();
    if (d.has("color")) light.color = d["color"].vec3();
    if (d.has("intensity")) light.intensity = float(d["intensity"].number_in(0, 1e30, false, false, "0 to 1e30"));
    if (d.has("range")) light.range = float(d["range"].number_in(0, 1e30, true, false, "> 0, at most 1e30"));
    if (spot) {
        light.direction = d["direction"].nonzero_vec3();
        if (d.has("outer_angle")) light.outer_angle = float(d["outer_angle"].number_in(0, 90, true, false, "in (0, 90]"));
        if (d.has("inner_angle")) light.inner_angle = float(d["inner_angle"].number_in(0, 90, false, false, "in [0, 90]"));
        if (!(light.inner_angle < light.outer_angle))
            (d.has("inner_angle") ? d["inner_angle"] : d["outer_angle"]).fail("inner_angle must be less than outer_angle");
        if (d.has("shadow") && light.outer_angle > 80.0f)
            d["outer_angle"].fail("a spot light with a shadow has outer_angle at most 80");
    }
    if (d.has("shadow")) light.shadow = read_shadow(d["shadow"], lights);  // a point light's: a cube map
    return light;
}

}  // namespace

void read_lights(const Node& n, Lights& l, int version) {
    n.expect_object({"ambient", "directional"}, {"point", "spot"}, version);
    if (n.has("ambient")) l.ambient = n["ambient"].vec3();
    for (const char* kind : {"point", "spot"}) {
        if (!n.has(kind)) continue;
        const Node list = n[kind];
        const size_t count = list.array_size();
        if (l.punctual.size() + count > Lights::kMaxPunctual)
            list.fail("at most " + std::to_string(Lights::kMaxPunctual) + " point and spot lights together");
        for (size_t i = 0; i < count; ++i) l.punctual.push_back(read_punctual(list.at(i), kind[0] == 's', l));
    }
    if (!n.has("directional")) return;
    const Node list = n["directional"];
    const size_t count = list.array_size();
    if (count > Lights::kMaxDirectional) list.fail("at most 8 directional lights, got " + std::to_string(count));
    for (size_t i = 0; i < count; ++i) {
        const Node d = list.at(i);
        d.expect_object({"direction", "color"}, {"shadow"}, version);
        DirectionalLight light;
        light.direction = d["direction"].nonzero_vec3();
        light.color = d["color"].vec3();  // no default in the spec: required
        if (d.has("shadow")) light.shadow = read_shadow(d["shadow"], l);
        l.directional.push_back(light);
    }
}

}  // namespace softraster::scene_json
