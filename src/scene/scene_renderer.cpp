#include "softraster/scene/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "scene/object_state.h"
#include "scene/record_sky_draw.h"
#include "scene/record_surface_draw.h"
#include "softraster/context.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/worker_pool.h"

namespace softraster {
namespace {

// Flat shading uses the world-space face normal of each triangle before clipping. Giving
// every triangle its own corners that carry that normal (already in world space, so the
// shader's normal matrix is the identity) makes it an ordinary interpolated attribute.
std::shared_ptr<Mesh> world_face_normal_mesh(const Mesh& mesh, const glm::mat4& model) {
    auto out = std::make_shared<Mesh>();
    out->vertices.reserve(mesh.indices.size());
    out->indices.reserve(mesh.indices.size());
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        MeshVertex v[3];
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = mesh.vertices[mesh.indices[i + size_t(k)]];
            p[k] = glm::vec3(model * glm::vec4(v[k].position, 1.0f));
        }
        const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (int k = 0; k < 3; ++k) {
            v[k].normal = n;
            out->indices.push_back(uint32_t(out->vertices.size()));
            out->vertices.push_back(v[k]);
        }
    }
    return out;
}

// View-space depth (negative z: larger is nearer) of the center of the object-space bounding
// box of the vertices `indices` draws: the key blended objects are sorted by.
float view_depth_of_bounds_center(const Mesh& mesh, const std::vector<uint32_t>& indices, const glm::mat4& model_view) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    bool any = false;
    for (uint32_t i : indices) {
        const glm::vec3 p = mesh.vertices[i].position;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
        any = true;
    }
    if (!any) return 0.0f;
    return (model_view * glm::vec4(0.5f * (lo + hi), 1.0f)).z;
}

// A point or spot light's numbers for the shaders (lighting.h positional_light).
PositionalLight shader_numbers(const PunctualLight& l) {
    PositionalLight p;
    p.position = l.position;
    p.color = l.color * l.intensity;
    p.inv_range2 = l.range > 0.0f ? float(1.0 / (double(l.range) * double(l.range))) : 0.0f;
    p.spot = l.spot;
    if (l.spot) {
        p.spot_direction = glm::vec3(glm::normalize(glm::dvec3(l.direction)));
        const double cos_outer = std::cos(glm::radians(double(l.outer_angle))), cos_inner = std::cos(glm::radians(double(l.inner_angle)));
        const double scale = 1.0 / std::max(1e-3, cos_inner - cos_outer);
        p.cone_scale = float(scale);
        p.cone_offset = float(-cos_outer * scale);
    }
    return p;
}

LightSet light_set(const Lights& lights, const std::vector<PositionalLight>& positional) {
    LightSet set;
    set.positional = positional.data();
    set.positional_count = int(positional.size());
    set.ambient = lights.ambient;
    for (const DirectionalLight& l : lights.directional) {
        if (set.count == LightSet::kMax) break;
        set.to_light[size_t(set.count)] = -glm::normalize(l.direction);
        set.color[size_t(set.count)] = l.color;
        ++set.count;
    }
    return set;
}

// The draw of an object's wireframe: its triangles' edges, unlit in one color, opaque,
// writing depth unless the object says not to, with the object's depth test, stencil,
// scissor and color mask. (The object itself is drawn pushed back by polygon offset, so the
// edges win the depth test against it.)
SceneRenderer::Draw wireframe_draw(const SceneRenderer::Draw& object, const SceneObject& o, const Wireframe& wire) {
    SceneRenderer::Draw d;
    d.mesh = object.mesh;
    d.primitive = Topology::Lines;
    d.line_point_indices = std::make_shared<const std::vector<uint32_t>>(triangle_edges(*object.mesh));
    d.uniforms = object.uniforms;
    d.uniforms.color = glm::vec4(wire.color, 1.0f);
    d.uniforms.texture = nullptr;
    d.shading = Shading::Unlit;
    d.colored = false;
    d.state = object.state;
    d.state.blend = BlendMode::Opaque;
    d.state.alpha_test = d.state.alpha_to_coverage = d.state.noperspective = false;
    d.state.line_width = wire.width;
    d.state.depth_write = o.state.depth_write.value_or(true);
    return d;
}

bool has_vertex_colors(const Mesh& mesh) {
    return std::any_of(mesh.vertices.begin(), mesh.vertices.end(), [](const MeshVertex& v) { return v.color != glm::vec4(1.0f); });
}

void draw_object(Context& ctx, const SceneRenderer::Draw& d) {
    ctx.state = d.state;
    switch (d.shading) {
        case Shading::Unlit: record_surface_draw<Shading::Unlit>(ctx, d); break;
        case Shading::Flat: record_surface_draw<Shading::Flat>(ctx, d); break;
        case Shading::Gouraud: record_surface_draw<Shading::Gouraud>(ctx, d); break;
        case Shading::Lambert: record_surface_draw<Shading::Lambert>(ctx, d); break;
        case Shading::BlinnPhong: record_surface_draw<Shading::BlinnPhong>(ctx, d); break;
        case Shading::Phong: record_surface_draw<Shading::Phong>(ctx, d); break;
        case Shading::Pbr: record_surface_draw<Shading::Pbr>(ctx, d); break;
        case Shading::Normals: record_surface_draw<Shading::Normals>(ctx, d); break;
        case Shading::Depth: record_surface_draw<Shading::Depth>(ctx, d); break;
    }
}

// A depth-only pass over every opaque triangle object (shadow maps, ambient occlusion): the
// objects' matrices `view_projection` * model, only depth written, each object's state
// from `state_of`.
struct DepthPass {
    Framebuffer fb;
    std::vector<SceneRenderer::Draw> draws;
    std::unique_ptr<Context> ctx;  // the recorded pass

    template <class StateOf>
    DepthPass(const Scene& scene, int width, int height, const glm::dmat4& view_projection, StateOf&& state_of) : fb(width, height) {
        for (const SceneObject& o : scene.objects) {
            if (o.primitive != Topology::Triangles || o.material.blend != BlendMode::Opaque) continue;
            RenderState st = state_of(o);
            st.color_write = false;
            SceneRenderer::Draw d{o.mesh.get(), nullptr, Topology::Triangles, nullptr, {}, st, Shading::Unlit, false};
            d.uniforms.mvp = glm::mat4(view_projection * glm::dmat4(o.model));
            draws.push_back(std::move(d));
        }
    }
    void render(WorkerPool* pool) {
        if (!ctx) {
            ctx = std::make_unique<Context>(fb, pool);
            ctx->clear_depth(1.0f);  // (no color is drawn, nor read)
            for (const SceneRenderer::Draw& d : draws) draw_object(*ctx, d);
        }
        ctx->execute();
    }
};

}  // namespace

// A light's shadow map: the depth of the nearest caster per texel, seen through each face's
// S (shadow_matrix), filled by a depth pass of the scene's opaque triangles before each frame.
struct SceneRenderer::ShadowPass {
    std::vector<DepthPass> faces;  // one, or a point light's six
    ShadowMap map;

    explicit ShadowPass(const ShadowSettings& s) {
        faces.reserve(6);  // never moved: the map's faces point into their framebuffers
        map.size = s.size;
        map.pcf = s.pcf;
    }
    // A face seen through `matrix`; b is the bias along `travel`, the way the light goes.
    // Both faces of the casters cast, pushed back by their slope.
    void add_face(const Scene& scene, const ShadowSettings& s, const glm::mat4& matrix, const glm::vec3& travel) {
        DepthPass& pass = faces.emplace_back(scene, s.size, s.size, glm::dmat4(matrix), [&](const SceneObject&) {
            RenderState st;
            st.cull = CullMode::None;
            st.polygon_offset_factor = s.slope_bias;
            return st;
        });
        ShadowFace& f = map.face[faces.size() - 1];
        f.depth = pass.fb.depth_data();
        f.matrix = matrix;
        f.offset = shadow_offset(s, travel);
        map.faces = int(faces.size());
    }
};

// Ambient occlusion's depth: the camera's view of the opaque objects, one sample per pixel
// of the picture as drawn (supersampled), each object culled as it is in the picture.
struct SceneRenderer::OcclusionPass {
    DepthPass pass;
    glm::mat4 projection;
    AmbientOcclusionSettings settings;
};

// The environment behind the scene: one triangle, no depth, before every object.
struct SceneRenderer::Sky {
    SkyShader shader;
    std::array<SkyVertex, 3> vertices;
    void record(Context& ctx) const {
        RenderState st;
        st.cull = CullMode::None;
        st.depth_test = st.depth_write = false;
        ctx.state = st;
        record_sky_draw(ctx, shader, vertices);
    }
};

SceneRenderer::SceneRenderer(const Scene& scene, unsigned threads)
    : scene_(scene), pool_(threads > 1 ? std::make_unique<WorkerPool>(threads) : nullptr) {
    const glm::mat4 view = view_matrix(scene.camera);
    const glm::mat4 proj = projection_matrix(scene.camera, scene.width, scene.height);
    if (scene.environment && scene.environment->background)
        sky_ = std::make_unique<Sky>(
            Sky{{&scene.environment->picture, scene.environment->intensity, scene.tone_mapping}, sky_triangle(view, proj)});
    for (const PunctualLight& l : scene.lights.punctual) positional_lights_.push_back(shader_numbers(l));
    LightSet lights = light_set(scene.lights, positional_lights_);
    // Shadows: directional lights first, then spot lights, each with its pass.
    static_assert(Lights::kMaxShadowed == size_t(kMaxShadowedLights));
    // (The bounds walk every vertex: only scenes with a shadow pay for them.)
    std::optional<Bounds> scene_bounds;
    auto bounds = [&]() -> const Bounds& { return scene_bounds ? *scene_bounds : scene_bounds.emplace(shadow_bounds(scene)); };
    auto add_shadow = [&](const ShadowSettings& s) -> ShadowPass& {
        shadow_passes_.push_back(std::make_unique<ShadowPass>(s));
        lights.shadows[size_t(lights.shadow_count++)] = &shadow_passes_.back()->map;
        return *shadow_passes_.back();
    };
    for (size_t i = 0; i < scene.lights.directional.size() && i < size_t(LightSet::kMax); ++i)
        if (const DirectionalLight& l = scene.lights.directional[i]; l.shadow) {
            add_shadow(*l.shadow).add_face(scene, *l.shadow, shadow_matrix(l, bounds()), l.direction);
            lights.shadow_of[i] = lights.shadow_count - 1;
        }
    for (size_t i = 0; i < scene.lights.punctual.size(); ++i) {
        const PunctualLight& l = scene.lights.punctual[i];
        if (!l.shadow) continue;
        ShadowPass& shadow = add_shadow(*l.shadow);
        if (l.spot) {
            shadow.add_face(scene, *l.shadow, shadow_matrix(l, bounds()), l.direction);
        } else {  // a cube, each face's bias along its axis (the depth it stores grows along it)
            for (int f = 0; f < 6; ++f) shadow.add_face(scene, *l.shadow, shadow_matrix(l, bounds(), f), cube_face_axis(f));
            shadow.map.light = l.position;
        }
        positional_lights_[i].shadow = lights.shadow_count - 1;
    }
    if (scene.ambient_occlusion) {
        const int k = scene.supersample;
        occlusion_ = std::make_unique<OcclusionPass>(OcclusionPass{
            DepthPass(scene, scene.width * k, scene.height * k, glm::dmat4(proj) * glm::dmat4(view),
                      [](const SceneObject& o) {
                          RenderState st;
                          st.cull = o.cull;
                          st.front_face = o.front_face;
                          return st;
                      }),
            proj, *scene.ambient_occlusion});
    }

    struct Keyed {
        Draw draw;
        float depth;
        size_t index;  // in the file
    };
    std::vector<Keyed> opaque, blended;
    for (const SceneObject& o : scene.objects) {
        Draw d{o.mesh.get(), nullptr, o.primitive, nullptr, {}, {}, o.material.shading, has_vertex_colors(*o.mesh)};
        if (o.primitive != Topology::Triangles) {
            d.line_point_indices = std::make_shared<const std::vector<uint32_t>>(primitive_indices(*o.mesh, o.primitive));
            d.shading = Shading::Unlit;
        }
        SurfaceUniforms& u = d.uniforms;
        u.mvp = glm::mat4(glm::dmat4(proj) * glm::dmat4(view) * glm::dmat4(o.model));
        u.model = o.model;
        u.normal_matrix = glm::mat3(normal_matrix(o.model));
        u.eye = scene.camera.eye;
        u.lights = lights;
        u.color = o.material.color;
        u.specular = o.material.specular;
        u.has_specular = o.material.specular != glm::vec3(0.0f);
        u.shininess = o.material.shininess;
        u.texture = o.material.texture.get();
        u.sampler = o.material.sampler;
        u.metallic = o.material.metallic;
        u.roughness = o.material.roughness;
        u.emissive = o.material.emissive;
        u.occlusion_strength = o.material.occlusion_strength;
        u.metallic_roughness_texture = o.material.metallic_roughness_texture.get();
        u.occlusion_texture = o.material.occlusion_texture.get();
        u.emissive_texture = o.material.emissive_texture.get();
        u.normal_texture = o.material.normal_texture.get();
        u.normal_scale = o.material.normal_scale;
        u.tone_mapping = scene.tone_mapping;
        u.environment = scene.environment.get();
        if (d.shading == Shading::Flat) {
            d.flat_mesh = world_face_normal_mesh(*o.mesh, o.model);
            d.mesh = d.flat_mesh.get();
            u.normal_matrix = glm::mat3(1.0f);
        }
        // Point and spot lights and shadows need the surface position P, which the lambert
        // and flat shaders do not interpolate: blinn_phong's does, and without its specular
        // term it computes exactly their formula.
        if ((lights.positional_count || lights.shadow_count) && (d.shading == Shading::Lambert || d.shading == Shading::Flat)) {
            d.shading = Shading::BlinnPhong;
            u.has_specular = false;
        }
        const bool is_blended = o.material.blend != BlendMode::Opaque;
        d.state = render_state(o, scene.supersample);
        d.state.depth_write = o.state.depth_write.value_or(!is_blended);  // blended objects test but do not write
        const float depth =
            is_blended ? view_depth_of_bounds_center(*o.mesh, d.line_point_indices ? *d.line_point_indices : o.mesh->indices, view * o.model)
                       : 0.0f;
        const size_t index = size_t(&o - scene.objects.data());
        std::optional<Draw> wire;
        if (o.wireframe) {
            wire = wireframe_draw(d, o, *o.wireframe);
            d.state.polygon_offset_factor += 1.0f;
            d.state.polygon_offset_units += 1.0f;
        }
        auto& list = is_blended ? blended : opaque;
        list.push_back({std::move(d), depth, index});
        if (wire) list.push_back({std::move(*wire), depth, index});  // right after its object, whatever the order
    }
    // Opaque first in file order; then blended, farthest (most negative view z) first,
    // ties in file order. Or all in file order (version 2, draw_order "file").
    if (!scene.sorted) {
        for (Keyed& k : blended) opaque.push_back(std::move(k));
        std::stable_sort(opaque.begin(), opaque.end(), [](const Keyed& a, const Keyed& b) { return a.index < b.index; });
        blended.clear();
    }
    std::stable_sort(blended.begin(), blended.end(), [](const Keyed& a, const Keyed& b) { return a.depth < b.depth; });
    for (auto* list : {&opaque, &blended})
        for (Keyed& k : *list) draws_.push_back(std::move(k.draw));
}

SceneRenderer::~SceneRenderer() = default;

size_t SceneRenderer::triangle_count() const {
    size_t n = 0;
    for (const Draw& d : draws_)
        if (d.primitive == Topology::Triangles) n += d.mesh->triangle_count();
    return n;
}

RenderStats SceneRenderer::render(Framebuffer& fb) const {
    for (const auto& shadow : shadow_passes_)
        for (DepthPass& face : shadow->faces) face.render(pool_.get());
    if (occlusion_) occlusion_->pass.render(pool_.get());
    if (!ctx_) {
        ctx_ = std::make_unique<Context>(fb, pool_.get());
        ctx_->clear(scene_.background, 1.0f, scene_.clear_stencil);
        if (sky_) sky_->record(*ctx_);
        for (const Draw& d : draws_) draw_object(*ctx_, d);
    }
    ctx_->set_framebuffer(fb);
    ctx_->execute();
    return {ctx_->fragments_shaded()};
}

Framebuffer SceneRenderer::make_framebuffer() const {
    return Framebuffer(scene_.width * scene_.supersample, scene_.height * scene_.supersample, scene_.samples, scene_.color_space);
}

bool SceneRenderer::fits(const Framebuffer& fb) const {
    return fb.width() == scene_.width * scene_.supersample && fb.height() == scene_.height * scene_.supersample &&
           fb.samples() == scene_.samples && fb.color_space() == scene_.color_space;
}

Image SceneRenderer::resolve(const Framebuffer& fb) const {
    Image picture;
    softraster::resolve(fb, picture, pool_.get());
    if (occlusion_) {
        const Framebuffer& depth = occlusion_->pass.fb;
        apply_ambient_occlusion(
            picture, ambient_occlusion(depth.depth_data(), depth.width(), depth.height(), occlusion_->projection, occlusion_->settings, pool_.get()),
            scene_.color_space);
    }
    if (scene_.supersample == 1) return picture;  // (not a copy of a whole picture)
    return downsample_box(picture, scene_.supersample, scene_.color_space);
}

Image SceneRenderer::render() const {
    Framebuffer fb = make_framebuffer();
    render(fb);
    return resolve(fb);
}

}  // namespace softraster
