// Lesson 15: shadow mapping (阴影映射, Williams 1978). Render the scene's depth as the light
// sees it; then a point is in shadow when something nearer to the light covers it there.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "../10-shaders/shaders.h"
#include "../common/pipeline.h"
#include "softraster/pipeline/resolve.h"

namespace course {

struct ShadowMap {
    int size = 0;
    glm::mat4 light_view_projection{1.0f};  // world -> the light's clip space (lesson 6)
    std::vector<float> depth;                // size x size, row 0 at the top: the nearest depth the light sees
};

// Pass 1: the scene from the light, depth only (no color is written), into a size x size map.
struct DepthOnlyShader {
    using Vertex = MeshIn;
    using Varyings = NoVaryings;
    glm::mat4 model_light_view_projection;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.unused = 0.0f;
        return model_light_view_projection * glm::vec4(in.position, 1.0f);
    }
    bool fragment(const Varyings&, const softraster::FragCoord&, glm::vec4& c) const {
        c = glm::vec4(1.0f);
        return true;
    }
};

struct Placed {
    const std::vector<MeshIn>* vertices;
    const std::vector<uint32_t>* indices;
    glm::mat4 model;
};

inline ShadowMap render_shadow_map(const std::vector<Placed>& objects, const glm::mat4& light_view_projection, int size) {
    softraster::Framebuffer fb(size, size);
    softraster::Context ctx(fb);
    ctx.clear(glm::vec4(0.0f), 1.0f);
    ctx.state.cull = softraster::CullMode::None;
    ctx.state.color_write = false;
    for (const Placed& o : objects)
        ctx.draw(softraster::Topology::Triangles, DepthOnlyShader{light_view_projection * o.model}, std::span<const MeshIn>(*o.vertices),
                 std::span<const uint32_t>(*o.indices));
    ctx.finish();
    return {size, light_view_projection, softraster::depth_picture(fb).values};
}

// Pass 2, per pixel: the point's place in the map and its depth from the light (lesson 8's
// viewport for the light's picture). In shadow when the map holds something nearer by more
// than `bias`: without a bias a surface shadows itself in stripes where its own depth,
// stored at the map's resolution, rounds above its true depth ("shadow acne", 阴影失真).
inline bool in_shadow(const ShadowMap& map, const glm::vec3& world, float bias) {
    const glm::vec4 clip = map.light_view_projection * glm::vec4(world, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    const int x = int(std::floor((ndc.x + 1.0f) * 0.5f * float(map.size))), y = int(std::floor((1.0f - ndc.y) * 0.5f * float(map.size)));
    if (x < 0 || y < 0 || x >= map.size || y >= map.size) return false;  // outside the light's view: lit
    const float depth = (ndc.z + 1.0f) * 0.5f;
    return depth - bias > map.depth[size_t(y) * size_t(map.size) + size_t(x)];
}

// The camera's pass: Lambert, darkened where the shadow map says so.
struct ShadowedShader {
    using Vertex = MeshIn;
    using Varyings = SurfaceVaryings;
    glm::mat4 model, view_projection;
    glm::vec3 to_light, albedo;
    const ShadowMap* map;  // none: no shadows
    float bias;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        const glm::vec4 world = model * glm::vec4(in.position, 1.0f);
        out = {glm::mat3(model) * in.normal, glm::vec3(world), in.color};  // (local carries the world position here)
        return view_projection * world;
    }
    bool fragment(const Varyings& in, const softraster::FragCoord&, glm::vec4& c) const {
        const float lit = map && in_shadow(*map, in.local, bias) ? 0.0f : std::max(0.0f, glm::dot(glm::normalize(in.normal), to_light));
        c = glm::vec4(albedo * (0.2f + 0.8f * lit), 1.0f);
        return true;
    }
};

}  // namespace course
