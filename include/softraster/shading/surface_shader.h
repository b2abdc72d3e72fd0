// The scene format's seven shading models as one shader template (spec "Shading").
//
// SurfaceShader<Model, Textured> is a Shader (pipeline/shader.h): the model and whether a
// texture is sampled are template arguments, so each combination's fragment code is compiled
// on its own with no per-pixel branch on the shading model.
#pragma once
#include <array>
#include <cmath>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "softraster/pipeline/shader.h"
#include "softraster/pipeline/simd_avx2.h"
#include "softraster/shading/lighting.h"
#include "softraster/shading/normal_mapping.h"
#include "softraster/shading/pbr.h"
#include "softraster/shading/surface_uniforms.h"
#include "softraster/shading/surface_vertex.h"
#include "softraster/shading/texture.h"

namespace softraster {

// A varying present only when a condition holds; otherwise an empty member that takes no
// space, so each shader interpolates exactly what its formula reads.
template <int Tag>
struct NoVarying {};
template <bool Present, class T, int Tag>
using MaybeVarying = std::conditional_t<Present, T, NoVarying<Tag>>;

template <Shading M, bool Textured, bool Colored, bool NormalMapped = false>
struct SurfaceVaryings {
    static constexpr bool kSpecular = M == Shading::BlinnPhong || M == Shading::Phong;
    static constexpr bool kPbr = M == Shading::Pbr;
    static constexpr bool kLit = M == Shading::Flat || M == Shading::Lambert || kSpecular || kPbr;
    static constexpr bool kBase = M != Shading::Normals && M != Shading::Depth;  // reads color and texture
    static constexpr bool kWorld = kSpecular || kPbr;
    static constexpr bool kNormal = kLit || M == Shading::Normals;
    static constexpr bool kTangent = NormalMapped;  // pbr with a normal map
    static_assert(!NormalMapped || (kPbr && Textured), "normal maps are read by textured pbr shaders");
    static constexpr bool kIntensity = M == Shading::Gouraud;
    static constexpr bool kUv = kBase && Textured;
    static constexpr bool kColor = kBase && Colored;
    static constexpr bool kAny = kWorld || kNormal || kIntensity || kUv || kColor;

    [[no_unique_address]] MaybeVarying<kWorld, glm::vec3, 0> world;          // world-space position P
    [[no_unique_address]] MaybeVarying<kNormal, glm::vec3, 1> normal;        // world-space normal
    [[no_unique_address]] MaybeVarying<kTangent, glm::vec4, 7> tangent;      // world-space tangent, w the bitangent's sign
    [[no_unique_address]] MaybeVarying<kIntensity, glm::vec3, 2> intensity;  // Gouraud: lighting at the vertex
    [[no_unique_address]] MaybeVarying<kUv, glm::vec2, 3> uv;
    [[no_unique_address]] MaybeVarying<kUv, glm::vec4, 6> uv_derivatives;  // d(u, v)/dx, d(u, v)/dy: filled per pixel
    [[no_unique_address]] MaybeVarying<kColor, glm::vec4, 4> color;          // vertex color
    [[no_unique_address]] MaybeVarying<!kAny, float, 5> unused;              // a struct has at least one float

    // Where each present varying starts among the struct's floats (empty ones take none).
    static constexpr int kWorldAt = 0;
    static constexpr int kNormalAt = kWorldAt + 3 * kWorld;
    static constexpr int kTangentAt = kNormalAt + 3 * kNormal;
    static constexpr int kIntensityAt = kTangentAt + 4 * kTangent;
    static constexpr int kUvAt = kIntensityAt + 3 * kIntensity;
    static constexpr int kUvDerivativesAt = kUvAt + 2 * kUv;
    static constexpr int kColorAt = kUvDerivativesAt + 4 * kUv;
    static constexpr int kFloats = kAny ? kColorAt + 4 * kColor : 1;
};

// Colored: the mesh has vertex colors other than white (otherwise the term is 1 and is
// not interpolated at all). NormalMapped: pbr with a normal map, whose vertices carry tangents.
template <Shading Model, bool Textured, bool Colored = true, bool NormalMapped = false>
struct SurfaceShader {
    using Vertex = std::conditional_t<NormalMapped, TangentVertex, MeshVertex>;
    using Varyings = SurfaceVaryings<Model, Textured, Colored, NormalMapped>;
    static constexpr bool kPure = true;  // never discards, no side effects
    static constexpr bool kVaryingsOnly = Model != Shading::Depth;  // (depth reads the fragment's z)
    // A texture's level of detail needs the derivatives of uv (shader.h).
    static constexpr int kDerivativeOf = Varyings::kUv ? Varyings::kUvAt : -1;
    static constexpr int kDerivativeAt = Varyings::kUvDerivativesAt;
    static constexpr uint64_t kFlat = Varyings::kUv ? varying_bits(sizeof(float) * kDerivativeAt, sizeof(glm::vec4)) : 0;
    static constexpr Specular kSpecularModel = Model == Shading::Phong ? Specular::Phong : Specular::BlinnPhong;
    const SurfaceUniforms* u;

    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        if constexpr (Varyings::kWorld) out.world = glm::vec3(u->model * glm::vec4(in.position, 1.0f));
        if constexpr (Varyings::kNormal) out.normal = u->normal_matrix * in.normal;
        // A tangent lies in the surface, so it moves with the model matrix itself.
        if constexpr (Varyings::kTangent) out.tangent = glm::vec4(glm::mat3(u->model) * glm::vec3(in.tangent), in.tangent.w);
        if constexpr (Varyings::kIntensity) {
            const glm::vec3 n = glm::normalize(u->normal_matrix * in.normal);
            out.intensity = diffuse_intensity(u->lights, n);
            if (u->lights.positional_count) {
                glm::vec3 unused(0.0f);
                positional_terms<false>(u->lights, n, glm::vec3(u->model * glm::vec4(in.position, 1.0f)), glm::vec3(0.0f), glm::vec3(0.0f), 0.0f,
                                        out.intensity, unused);
            }
        }
        if constexpr (Varyings::kUv) out.uv = in.uv;
        if constexpr (Varyings::kColor) out.color = in.color;
        return u->mvp * glm::vec4(in.position, 1.0f);
    }

#if SOFTRASTER_HAS_AVX2_PATH
    // vertex() for eight vertices (shader.h, LaneVertexShader): each product in glm's order,
    // mat4 * vec4 as (m0 x + m1 y) + (m2 z + m3 w) and mat3 * vec3 as (m0 x + m1 y) + m2 z,
    // lane by lane, so every varying and clip coordinate has vertex()'s bits (w = 1: m3 w is
    // m3). Not for Gouraud's per-vertex lighting or tangents.
    SOFTRASTER_AVX2_TARGET void vertex_lanes(const Vertex* in, std::array<simd::f8, kVaryingCount<Varyings>>& out, std::array<simd::f8, 4>& clip) const
        requires(!Varyings::kIntensity && !Varyings::kTangent) {
        using simd::f8;
        constexpr size_t kStride = sizeof(Vertex);
        f8 a[4], b[4];  // (x, y, z, normal x) and (normal y, normal z, u, v) of each vertex
        simd::load_columns(&in->position, kStride, a);
        simd::load_columns(&in->normal.y, kStride, b);
        const f8 &x = a[0], &y = a[1], &z = a[2];
        // (Results through a reference: a lambda is not compiled for AVX2, and where it is not
        // inlined, as in the unit tests' unoptimized build, a vector it returns goes astray.)
        auto point = [&](const glm::mat4& m, int r, f8& p) { p = (m[0][r] * x + m[1][r] * y) + (m[2][r] * z + m[3][r]); };
        out.fill(f8{});
        if constexpr (Varyings::kWorld)
            for (int r = 0; r < 3; ++r) point(u->model, r, out[size_t(Varyings::kWorldAt + r)]);
        if constexpr (Varyings::kNormal) {
            const glm::mat3& m = u->normal_matrix;
            for (int r = 0; r < 3; ++r) out[size_t(Varyings::kNormalAt + r)] = (m[0][r] * a[3] + m[1][r] * b[0]) + m[2][r] * b[1];
        }
        if constexpr (Varyings::kUv) out[size_t(Varyings::kUvAt)] = b[2], out[size_t(Varyings::kUvAt + 1)] = b[3];
        if constexpr (Varyings::kColor) {
            f8 c[4];
            simd::load_columns(&in->color, kStride, c);
            for (size_t k = 0; k < 4; ++k) out[size_t(Varyings::kColorAt) + k] = c[k];
        }
        for (int r = 0; r < 4; ++r) point(u->mvp, r, clip[size_t(r)]);
    }
#endif

    bool fragment(const Varyings& in, const FragCoord& frag, glm::vec4& out) const {
        if constexpr (Model == Shading::Depth) {
            out = glm::vec4(frag.z, frag.z, frag.z, 1.0f);
        } else if constexpr (Model == Shading::Normals) {
            out = glm::vec4(0.5f * glm::normalize(in.normal) + 0.5f, 1.0f);
        } else {
            glm::vec4 base = u->color;
            if constexpr (Varyings::kColor) base *= in.color;
            if constexpr (Varyings::kUv) {
                const glm::vec4 d = in.uv_derivatives;
                if (Model != Shading::Pbr || u->texture) base *= u->texture->sample(in.uv, UvDerivatives{d.x, d.y, d.z, d.w}, u->sampler);
            }
            if constexpr (Model == Shading::Unlit) {
                out = base;
            } else if constexpr (Model == Shading::Pbr) {
                out = glm::vec4(pbr_rgb(in, base), base.a);
            } else if constexpr (Model == Shading::Gouraud) {
                out = glm::vec4(glm::vec3(base) * in.intensity, base.a);
            } else {  // Lambert, Flat (N is the face normal), BlinnPhong, Phong
                LightVisibility<float> vis = kFullyLit;  // shadows need P: the scene renderer draws them with blinn_phong
                if constexpr (Varyings::kWorld) light_visibility(u->lights, in.world, vis);
                const glm::vec3 n = glm::normalize(in.normal);
                glm::vec3 diffuse = diffuse_intensity(u->lights, n, vis), spec(0.0f);
                if constexpr (Varyings::kSpecular) {
                    if (u->has_specular || u->lights.positional_count) {
                        const glm::vec3 v = glm::normalize(u->eye - in.world);
                        if (u->has_specular) {
                            spec = specular_term<kSpecularModel>(u->lights, n, v, u->specular, u->shininess, vis);
                            positional_terms<true, kSpecularModel>(u->lights, n, in.world, v, u->specular, u->shininess, diffuse, spec, vis);
                        } else {
                            positional_terms<false>(u->lights, n, in.world, v, u->specular, u->shininess, diffuse, spec, vis);
                        }
                    }
                }
                glm::vec3 rgb = glm::vec3(base) * diffuse;
                if constexpr (Varyings::kSpecular)
                    if (u->has_specular) rgb += spec;
                out = glm::vec4(rgb, base.a);
            }
            if (u->tone_mapping.active()) out = tone_map(u->tone_mapping, out);  // the light becomes a color
        }
        return true;
    }

    // pbr: the metallic-roughness BRDF (pbr.h) over the lights, ambient light on the diffuse
    // color times the occlusion, and the emissive color.
    glm::vec3 pbr_rgb(const Varyings& in, const glm::vec4& base) const {
        float metallic = u->metallic, roughness = u->roughness, occlusion = 1.0f;
        glm::vec3 emissive = u->emissive;
        if constexpr (Varyings::kUv) {
            const glm::vec4 dv = in.uv_derivatives;
            const UvDerivatives d{dv.x, dv.y, dv.z, dv.w};
            if (u->metallic_roughness_texture) {
                const glm::vec4 t = u->metallic_roughness_texture->sample(in.uv, d, u->sampler);
                roughness *= t.g, metallic *= t.b;
            }
            if (u->occlusion_texture) occlusion = 1.0f + u->occlusion_strength * (u->occlusion_texture->sample(in.uv, d, u->sampler).r - 1.0f);
            if (u->emissive_texture) emissive *= glm::vec3(u->emissive_texture->sample(in.uv, d, u->sampler));
        }
        const float clamped_roughness = std::max(kMinRoughness, roughness);
        const PbrSurface s = pbr_surface(glm::vec3(base), metallic, clamped_roughness);
        glm::vec3 n = glm::normalize(in.normal);
        if constexpr (Varyings::kTangent) {
            const glm::vec4 dv = in.uv_derivatives;
            const glm::vec4 m = u->normal_texture->sample(in.uv, UvDerivatives{dv.x, dv.y, dv.z, dv.w}, u->sampler);
            n = mapped_normal(in.normal, in.tangent, glm::vec3(m), u->normal_scale);
        }
        const glm::vec3 v = glm::normalize(u->eye - in.world);
        const float nv = std::max(0.0f, glm::dot(n, v));
        LightVisibility<float> vis = kFullyLit;
        light_visibility(u->lights, in.world, vis);
        glm::vec3 rgb = u->lights.ambient * s.diffuse * occlusion;
        for (int i = 0; i < u->lights.count; ++i) rgb += light_color(u->lights, i, vis) * pbr_light(s, n, v, u->lights.to_light[size_t(i)], nv);
        for (int i = 0; i < u->lights.positional_count; ++i) {
            glm::vec3 l;
            const PositionalLight& light = u->lights.positional[i];
            const glm::vec3 c = positional_light(light, in.world, l) * vis[size_t(light.shadow)];
            rgb += c * pbr_light(s, n, v, l, nv);
        }
        if (u->environment) rgb += environment_light(*u->environment, s.diffuse, s.f0, n, v, nv, clamped_roughness, occlusion);
        return rgb + emissive;
    }

    simd::vec3x8 pbr_rgb8(const std::array<simd::f8, kVaryingCount<Varyings>>& in, const std::array<simd::f8, 4>& base) const {
        using namespace simd;
        f8 metallic = splat(u->metallic), roughness = splat(u->roughness), occlusion = splat(1.0f);
        vec3x8 emissive = splat3(u->emissive);
        if constexpr (Varyings::kUv) {
            constexpr size_t d = Varyings::kUvDerivativesAt;
            const std::array<f8, 4> dd{in[d], in[d + 1], in[d + 2], in[d + 3]};
            std::array<f8, 4> t;
            auto sample = [&](const Texture* tex) { tex->sample8(in[Varyings::kUvAt], in[Varyings::kUvAt + 1], dd, u->sampler, t); };
            if (u->metallic_roughness_texture) {
                sample(u->metallic_roughness_texture);
                roughness *= t[1], metallic *= t[2];
            }
            if (u->occlusion_texture) {
                sample(u->occlusion_texture);
                occlusion = 1.0f + u->occlusion_strength * (t[0] - 1.0f);
            }
            if (u->emissive_texture) {
                sample(u->emissive_texture);
                emissive = {emissive.x * t[0], emissive.y * t[1], emissive.z * t[2]};
            }
        }
        const f8 clamped_roughness = max(splat(kMinRoughness), roughness);
        const PbrSurface8 s = pbr_surface(vec3x8{base[0], base[1], base[2]}, metallic, clamped_roughness);
        const vec3x8 normal{in[Varyings::kNormalAt], in[Varyings::kNormalAt + 1], in[Varyings::kNormalAt + 2]};
        vec3x8 n = normalize(normal);
        if constexpr (Varyings::kTangent) {
            constexpr size_t d = Varyings::kUvDerivativesAt, t = Varyings::kTangentAt;
            std::array<f8, 4> m;
            u->normal_texture->sample8(in[Varyings::kUvAt], in[Varyings::kUvAt + 1], {in[d], in[d + 1], in[d + 2], in[d + 3]}, u->sampler, m);
            n = mapped_normal(normal, {in[t], in[t + 1], in[t + 2]}, in[t + 3], {m[0], m[1], m[2]}, u->normal_scale);
        }
        const vec3x8 p{in[Varyings::kWorldAt], in[Varyings::kWorldAt + 1], in[Varyings::kWorldAt + 2]};
        const vec3x8 v = normalize({u->eye.x - p.x, u->eye.y - p.y, u->eye.z - p.z});
        const f8 nv = max(splat(0.0f), dot(n, v));
        LightVisibility<f8> vis;
        vis.fill(splat(1.0f));
        light_visibility(u->lights, p, vis);
        const glm::vec3 a = u->lights.ambient;
        vec3x8 rgb{a.x * s.diffuse.x * occlusion, a.y * s.diffuse.y * occlusion, a.z * s.diffuse.z * occlusion};
        auto add = [&](const vec3x8& c, const vec3x8& l) {
            const vec3x8 f = pbr_light(s, n, v, l, nv);
            rgb.x += c.x * f.x, rgb.y += c.y * f.y, rgb.z += c.z * f.z;
        };
        for (int i = 0; i < u->lights.count; ++i) {
            const glm::vec3 l = u->lights.to_light[size_t(i)];
            vec3x8 c;
            light_color(u->lights, i, vis, c);
            add(c, splat3(l));
        }
        for (int i = 0; i < u->lights.positional_count; ++i) {
            vec3x8 l;
            const PositionalLight& light = u->lights.positional[i];
            const vec3x8 c = positional_light(light, p, l);
            const f8& k = vis[size_t(light.shadow)];
            add({c.x * k, c.y * k, c.z * k}, l);
        }
        if (u->environment) {
            vec3x8 e;
            environment_light8(*u->environment, s.diffuse, s.f0, n, v, nv, clamped_roughness, occlusion, e);
            rgb.x += e.x, rgb.y += e.y, rgb.z += e.z;
        }
        return {rgb.x + emissive.x, rgb.y + emissive.y, rgb.z + emissive.z};
    }

    // The uniforms the batch formulas use for every group, in eight lanes: broadcast once per
    // call that shades many groups (shader_layout.h, the queue's flush) rather than per group.
    struct BatchConstants {
        std::array<simd::f8, 4> color;
        simd::vec3x8 ambient;
        bool tone_mapped;
    };
    BatchConstants batch_constants() const {
        using simd::splat;
        return {{splat(u->color.r), splat(u->color.g), splat(u->color.b), splat(u->color.a)},
                simd::splat3(u->lights.ambient),
                u->tone_mapping.active()};
    }

    // The same formulas for eight fragments of a row (fragment_shading.h) ...
    void fragment_batch(const std::array<simd::f8, kVaryingCount<Varyings>>& in, simd::f8 z, bool front_facing,
                        std::array<simd::f8, 4>& out) const {
        fragment_batch(batch_constants(), in, z, front_facing, out);
    }
    void fragment_batch(const BatchConstants& k, const std::array<simd::f8, kVaryingCount<Varyings>>& in, simd::f8 z, bool,
                        std::array<simd::f8, 4>& out) const {
        if constexpr (Varyings::kUv) {
            std::array<simd::f8, 4> tex;
            const bool textured = Model != Shading::Pbr || u->texture;
            if (textured) u->texture->sample8(in[Varyings::kUvAt], in[Varyings::kUvAt + 1], uv_derivatives(in), u->sampler, tex);
            shade_batch(k, in, z, textured ? &tex : nullptr, out);
        } else {
            shade_batch(k, in, z, nullptr, out);
        }
    }
    // ... and for two groups (a row of 2x2 quads' two rows, or any two), whose texture lookups
    // go together (Texture::sample_pair).
    using Batch = std::array<simd::f8, kVaryingCount<Varyings>>;
    void fragment_pair(const Batch& in0, const Batch& in1, simd::f8 z0, simd::f8 z1, bool, std::array<simd::f8, 4>& out0,
                       std::array<simd::f8, 4>& out1) const requires(Varyings::kUv) {
        std::array<simd::f8, 4> tex0, tex1;
        const bool textured = Model != Shading::Pbr || u->texture;
        if (textured)
            u->texture->sample_pair(in0[Varyings::kUvAt], in0[Varyings::kUvAt + 1], in1[Varyings::kUvAt], in1[Varyings::kUvAt + 1],
                                    uv_derivatives(in0), uv_derivatives(in1), u->sampler, tex0, tex1);
        const BatchConstants k = batch_constants();
        shade_batch(k, in0, z0, textured ? &tex0 : nullptr, out0);
        shade_batch(k, in1, z1, textured ? &tex1 : nullptr, out1);
    }

    // ... and for four groups (two such pairs side by side, or any four), whose lookups go
    // together too (Texture::sample_four). Not for PBR: its four inlined shadings made its draw
    // code the slowest file of the build by a quarter more, and its frame no faster
    // (docs/performance.md, "Four groups a call").
    void fragment_four(const Batch (&in)[4], const simd::f8 (&z)[4], bool, std::array<simd::f8, 4> (&out)[4]) const
        requires(Varyings::kUv && Model != Shading::Pbr) {
        std::array<simd::f8, 4> tex[4];  // (not PBR: the texture is always there)
        static_assert(Varyings::kUvDerivativesAt == Varyings::kUvAt + 2, "u, v and their derivatives in a row, as the lookup reads them");
        constexpr size_t uv = Varyings::kUvAt;
        const simd::f8* const at[4] = {&in[0][uv], &in[1][uv], &in[2][uv], &in[3][uv]};
        u->texture->sample_four(at, u->sampler, tex);
        const BatchConstants k = batch_constants();
        for (size_t g = 0; g < 4; ++g) shade_batch(k, in[g], z[g], &tex[g], out[g]);
    }

private:
    static std::array<simd::f8, 4> uv_derivatives(const Batch& in) {
        constexpr size_t d = Varyings::kUvDerivativesAt;
        return {in[d], in[d + 1], in[d + 2], in[d + 3]};
    }
    // The formulas with the base color texture's value `tex` looked up (null: none).
    void shade_batch(const BatchConstants& k, const Batch& in, simd::f8 z, const std::array<simd::f8, 4>* tex,
                     std::array<simd::f8, 4>& out) const {
        using namespace simd;
        static_assert(kVaryingCount<Varyings> == Varyings::kFloats, "varying layout");
        auto vec3_at = [&](int at) { return vec3x8{in[size_t(at)], in[size_t(at) + 1], in[size_t(at) + 2]}; };
        if constexpr (Model == Shading::Depth) {
            out = {z, z, z, splat(1.0f)};
        } else if constexpr (Model == Shading::Normals) {
            const vec3x8 n = normalize(vec3_at(Varyings::kNormalAt));
            out = {0.5f * n.x + 0.5f, 0.5f * n.y + 0.5f, 0.5f * n.z + 0.5f, splat(1.0f)};
        } else {
            std::array<f8, 4> base = k.color;
            if constexpr (Varyings::kColor)
                for (size_t c = 0; c < 4; ++c) base[c] *= in[size_t(Varyings::kColorAt) + c];
            if constexpr (Varyings::kUv)
                if (tex)
                    for (size_t c = 0; c < 4; ++c) base[c] *= (*tex)[c];
            if constexpr (Model == Shading::Unlit) {
                out = base;
            } else if constexpr (Model == Shading::Pbr) {
                const vec3x8 rgb = pbr_rgb8(in, base);
                out = {rgb.x, rgb.y, rgb.z, base[3]};
            } else if constexpr (Model == Shading::Gouraud) {
                const vec3x8 i = vec3_at(Varyings::kIntensityAt);
                out = {base[0] * i.x, base[1] * i.y, base[2] * i.z, base[3]};
            } else {  // Lambert, Flat, BlinnPhong, Phong
                LightVisibility<f8> vis;
                vis.fill(splat(1.0f));
                if constexpr (Varyings::kWorld) light_visibility(u->lights, vec3_at(Varyings::kWorldAt), vis);
                const vec3x8 n = normalize(vec3_at(Varyings::kNormalAt));
                vec3x8 d = diffuse_intensity<Varyings::kWorld>(u->lights, n, vis, k.ambient), spec{splat(0.0f), splat(0.0f), splat(0.0f)};
                if constexpr (Varyings::kSpecular) {
                    if (u->has_specular || u->lights.positional_count) {
                        const vec3x8 p = vec3_at(Varyings::kWorldAt);
                        const vec3x8 v = normalize({u->eye.x - p.x, u->eye.y - p.y, u->eye.z - p.z});
                        if (u->has_specular) {
                            spec = specular_term<kSpecularModel>(u->lights, n, v, u->specular, u->shininess, vis);
                            positional_terms<true, kSpecularModel>(u->lights, n, p, v, u->specular, u->shininess, d, spec, vis);
                        } else {
                            positional_terms<false>(u->lights, n, p, v, u->specular, u->shininess, d, spec, vis);
                        }
                    }
                }
                out = {base[0] * d.x, base[1] * d.y, base[2] * d.z, base[3]};
                if constexpr (Varyings::kSpecular) {
                    if (u->has_specular) {
                        out[0] += spec.x;
                        out[1] += spec.y;
                        out[2] += spec.z;
                    }
                }
            }
            if (k.tone_mapped) tone_map(u->tone_mapping, out);
        }
    }
};

}  // namespace softraster
