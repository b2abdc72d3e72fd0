// Each shading model on a known input, against the spec's formulas computed by hand.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>

#include <glm/trigonometric.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/context.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/shading/surface_shader.h"

using namespace softraster;

namespace {

SurfaceUniforms uniforms() {
    SurfaceUniforms u;
    u.eye = glm::vec3(0, 0, 5);
    u.lights.ambient = glm::vec3(0.1f, 0.2f, 0.3f);
    u.lights.count = 2;
    u.lights.to_light[0] = glm::vec3(0, 0, 1);                       // straight on
    u.lights.color[0] = glm::vec3(0.5f);
    u.lights.to_light[1] = glm::normalize(glm::vec3(0, 1, -1));      // behind the surface: no light
    u.lights.color[1] = glm::vec3(1.0f);
    u.color = glm::vec4(0.8f, 0.6f, 0.4f, 0.5f);
    u.specular = glm::vec3(0.3f);
    u.has_specular = true;
    u.shininess = 10.0f;
    return u;
}

// Every varying at hand; each shader takes the ones it has.
struct Inputs {
    glm::vec3 world{0.0f}, normal{0, 0, 1}, intensity{0.0f};
    glm::vec4 color{1.0f};
};

Inputs surface(glm::vec3 normal) {
    Inputs in;
    in.normal = normal;
    return in;
}

template <Shading M>
glm::vec4 shade(const SurfaceUniforms& u, const Inputs& in, float z = 0.25f) {
    using S = SurfaceShader<M, false, true>;
    typename S::Varyings v{};
    if constexpr (S::Varyings::kWorld) v.world = in.world;
    if constexpr (S::Varyings::kNormal) v.normal = in.normal;
    if constexpr (S::Varyings::kIntensity) v.intensity = in.intensity;
    if constexpr (S::Varyings::kColor) v.color = in.color;
    glm::vec4 c;
    EXPECT_TRUE((S{&u}.fragment(v, FragCoord{0, 0, z, true}, c)));
    return c;
}

void expect_vec4(glm::vec4 a, glm::vec4 b) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], 1e-5f) << "channel " << i;
}

}  // namespace

TEST(ShadingModels, Unlit) {
    const SurfaceUniforms u = uniforms();
    Inputs v = surface({0, 0, 1});
    v.color = glm::vec4(0.5f, 1, 1, 1);
    expect_vec4(shade<Shading::Unlit>(u, v), glm::vec4(0.4f, 0.6f, 0.4f, 0.5f));
}

TEST(ShadingModels, LambertAndFlat) {
    const SurfaceUniforms u = uniforms();
    // N.L0 = 1 -> I = ambient + 0.5; light 1 is behind (N.L1 < 0).
    const glm::vec3 I = glm::vec3(0.6f, 0.7f, 0.8f);
    const glm::vec4 expected(glm::vec3(0.8f, 0.6f, 0.4f) * I, 0.5f);
    expect_vec4(shade<Shading::Lambert>(u, surface({0, 0, 2})), expected);  // normalized after interpolation
    expect_vec4(shade<Shading::Flat>(u, surface({0, 0, 1})), expected);
}

TEST(ShadingModels, GrazingLightGivesAmbientOnly) {
    SurfaceUniforms u = uniforms();
    u.lights.to_light[0] = glm::vec3(1, 0, 0);  // N.L = 0
    expect_vec4(shade<Shading::Lambert>(u, surface({0, 0, 1})), glm::vec4(glm::vec3(0.8f, 0.6f, 0.4f) * u.lights.ambient, 0.5f));
}

TEST(ShadingModels, GouraudUsesTheInterpolatedIntensity) {
    const SurfaceUniforms u = uniforms();
    Inputs v = surface({0, 1, 0});
    v.intensity = glm::vec3(0.5f, 1.0f, 2.0f);
    expect_vec4(shade<Shading::Gouraud>(u, v), glm::vec4(0.4f, 0.6f, 0.8f, 0.5f));
    // The vertex stage computes the intensity from the transformed normal.
    MeshVertex in;
    in.normal = glm::vec3(0, 0, 1);
    SurfaceShader<Shading::Gouraud, false>::Varyings out;
    SurfaceShader<Shading::Gouraud, false>{&u}.vertex(in, out);
    EXPECT_NEAR(out.intensity.r, 0.6f, 1e-6f);
    EXPECT_NEAR(out.intensity.b, 0.8f, 1e-6f);
}

TEST(ShadingModels, BlinnPhong) {
    const SurfaceUniforms u = uniforms();
    Inputs v = surface({0, 0, 1});
    v.world = glm::vec3(3, 0, 1);  // V = normalize(eye - P) = normalize(-3, 0, 4)
    const glm::vec3 V = glm::normalize(glm::vec3(-3, 0, 4));
    const glm::vec3 H = glm::normalize(glm::vec3(0, 0, 1) + V);
    const float spec = std::pow(H.z, 10.0f);
    const glm::vec3 rgb = glm::vec3(0.8f, 0.6f, 0.4f) * glm::vec3(0.6f, 0.7f, 0.8f) + glm::vec3(0.5f * 0.3f * spec);
    expect_vec4(shade<Shading::BlinnPhong>(u, v), glm::vec4(rgb, 0.5f));
}

// Phong: max(0, R.V)^shininess with R = 2 (N.L) N - L, here by hand for L tilted in x.
TEST(ShadingModels, PhongReflectsTheLightAboutTheNormal) {
    SurfaceUniforms u = uniforms();
    u.lights.to_light[0] = glm::normalize(glm::vec3(1, 0, 2));
    Inputs v = surface({0, 0, 1});
    v.world = glm::vec3(2, 0, 1);  // V = normalize(eye - P) = normalize(-2, 0, 4): along R
    const glm::vec3 L = u.lights.to_light[0], V = glm::normalize(glm::vec3(-2, 0, 4));
    const glm::vec3 R(-L.x, 0, L.z);  // the mirror image of L about z
    const float spec = std::pow(std::max(0.0f, glm::dot(R, V)), 10.0f);
    EXPECT_NEAR(spec, 1.0f, 1e-5f);   // V lies along R: the highlight's center
    const glm::vec3 rgb = glm::vec3(0.8f, 0.6f, 0.4f) * (glm::vec3(0.1f, 0.2f, 0.3f) + 0.5f * L.z) + glm::vec3(0.5f * 0.3f * spec);
    expect_vec4(shade<Shading::Phong>(u, v), glm::vec4(rgb, 0.5f));
    // Blinn-Phong's highlight at the same place is also 1 (H = N), off it Phong's falls faster.
    v.world = glm::vec3(0, 0, 1);  // V = (0, 0, 1)
    const float phong = std::pow(glm::dot(R, glm::vec3(0, 0, 1)), 10.0f);
    const float blinn = std::pow(glm::normalize(L + glm::vec3(0, 0, 1)).z, 10.0f);
    EXPECT_LT(phong, blinn);
    EXPECT_NEAR(shade<Shading::Phong>(u, v).r - shade<Shading::BlinnPhong>(u, v).r, 0.15f * (phong - blinn), 1e-5f);
}

// A point light: inverse-square falloff, the range window and the spot cone, against
// values worked out by hand (docs/scene-format.md "Point and spot lights").
TEST(ShadingModels, PointAndSpotLightFalloff) {
    PositionalLight point;
    point.position = glm::vec3(0, 0, 2);
    point.color = glm::vec3(4.0f);  // intensity 4 at distance 2: exactly 1
    glm::vec3 l;
    EXPECT_NEAR(positional_light(point, glm::vec3(0), l).x, 1.0f, 1e-6f);
    EXPECT_NEAR(l.z, 1.0f, 1e-6f);
    point.inv_range2 = 1.0f / 8.0f;  // range sqrt(8): (d^2 / range^2)^2 = 1/4, window 3/4
    EXPECT_NEAR(positional_light(point, glm::vec3(0), l).x, 0.75f, 1e-6f);
    point.inv_range2 = 1.0f / 3.0f;  // range below the distance: nothing
    EXPECT_EQ(positional_light(point, glm::vec3(0), l).x, 0.0f);
    // At the light itself: finite (d^2 is held at 1e-8).
    EXPECT_TRUE(std::isfinite(positional_light(point, point.position, l).x));

    PositionalLight spot = point;
    spot.inv_range2 = 0.0f;
    spot.spot = true;
    spot.spot_direction = glm::vec3(0, 0, -1);
    const float cos_inner = std::cos(glm::radians(10.0f)), cos_outer = std::cos(glm::radians(30.0f));
    spot.cone_scale = 1.0f / (cos_inner - cos_outer);
    spot.cone_offset = -cos_outer * spot.cone_scale;
    EXPECT_NEAR(positional_light(spot, glm::vec3(0), l).x, 1.0f, 1e-5f);  // on the axis
    const float off = std::tan(glm::radians(20.0f)) * 2.0f;             // 20 degrees off the axis
    const float cd = std::cos(glm::radians(20.0f)), a = (cd - cos_outer) / (cos_inner - cos_outer);
    const glm::vec3 p(off, 0, 0);
    EXPECT_NEAR(positional_light(spot, p, l).x, 4.0f / (off * off + 4.0f) * a * a, 1e-5f);
    EXPECT_EQ(positional_light(spot, glm::vec3(2.0f, 0, 0), l).x, 0.0f);  // 45 degrees: outside
}

// The lambert term of a point light seen at an angle, through the blinn_phong shader without
// specular (as the scene renderer draws lambert surfaces lit by point lights).
TEST(ShadingModels, PointLightOnASurface) {
    SurfaceUniforms u = uniforms();
    u.lights.count = 0;
    u.has_specular = false;
    PositionalLight light;
    light.position = glm::vec3(1, 0, 1);
    light.color = glm::vec3(2.0f);
    u.lights.positional = &light;
    u.lights.positional_count = 1;
    Inputs v = surface({0, 0, 1});
    v.world = glm::vec3(0, 0, 0);  // d^2 = 2, N.L = 1/sqrt(2)
    const float i = 2.0f / 2.0f * (1.0f / std::sqrt(2.0f));
    expect_vec4(shade<Shading::BlinnPhong>(u, v), glm::vec4(0.8f * (0.1f + i), 0.6f * (0.2f + i), 0.4f * (0.3f + i), 0.5f));
}

TEST(ShadingModels, BlinnPhongShininessZeroIsPowZeroZeroIsOne) {
    SurfaceUniforms u = uniforms();
    u.shininess = 0.0f;
    u.lights.count = 1;
    u.lights.to_light[0] = glm::normalize(glm::vec3(0, 1, 0.001f));  // N.L > 0 barely
    Inputs v = surface({0, 0, 1});
    v.world = glm::vec3(0, -5, 0);  // V points up-ish so that N.H can be ~0
    const glm::vec4 c = shade<Shading::BlinnPhong>(u, v);
    const float diffuse = 0.5f * u.lights.to_light[0].z;
    EXPECT_NEAR(c.r, 0.8f * (0.1f + diffuse) + 0.5f * 0.3f, 1e-5f);  // pow(x, 0) = 1
}

TEST(ShadingModels, VaryingsHoldOnlyWhatTheModelReads) {
    EXPECT_EQ((kVaryingCount<SurfaceShader<Shading::Depth, false, false>::Varyings>), 1);  // placeholder only
    EXPECT_EQ((kVaryingCount<SurfaceShader<Shading::Lambert, false, false>::Varyings>), 3);
    // (a texture adds uv and its 4 derivatives, filled per pixel for the level of detail)
    EXPECT_EQ((kVaryingCount<SurfaceShader<Shading::Lambert, true, true>::Varyings>), 13);
    EXPECT_EQ((kVaryingCount<SurfaceShader<Shading::BlinnPhong, true, true>::Varyings>), 16);
    EXPECT_EQ((kVaryingCount<SurfaceShader<Shading::Gouraud, false, false>::Varyings>), 3);
}

TEST(ShadingModels, NormalsAndDepth) {
    const SurfaceUniforms u = uniforms();
    expect_vec4(shade<Shading::Normals>(u, surface({0, 0, -3})), glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
    expect_vec4(shade<Shading::Depth>(u, surface({0, 0, 1}), 0.625f), glm::vec4(0.625f, 0.625f, 0.625f, 1.0f));
}

// A blended triangle whose varyings are the same at every corner is shaded once (the tile
// back end's constant color), but only for a shader whose color is its varyings' alone: the
// depth shader's one varying is constant, and its color is each pixel's own depth.
TEST(ShadingModels, BlendedDepthIsShadedAtEveryPixel) {
    constexpr int W = 32, H = 32;
    SurfaceUniforms u;  // mvp: identity, the positions are in clip space
    const std::vector<MeshVertex> v = {{{-1, -1, -0.8f}}, {{3, -1, 0.8f}}, {{-1, 3, -0.8f}}};  // window z 0.1 at the left, 0.9 at x = 64
    const std::vector<uint32_t> indices = {0, 1, 2};
    for (const bool generic : {false, true}) {
        SCOPED_TRACE(generic ? "generic path" : "best path");
        simd::use_generic_path(generic);
        Framebuffer fb(W, H);
        Context ctx(fb);
        ctx.clear(glm::vec4(0));
        ctx.state.cull = CullMode::None;
        ctx.state.depth_test = false;
        ctx.state.blend = BlendMode::Alpha;
        ctx.draw_triangles(SurfaceShader<Shading::Depth, false, false>{&u}, std::span<const MeshVertex>(v), std::span<const uint32_t>(indices));
        ctx.finish();
        for (const int x : {0, 15, 31}) {
            const float z = 0.1f + 0.8f * (float(x) + 0.5f) / 64.0f;
            EXPECT_NEAR(fb.color_data()[fb.sample_index(x, 0)].r, z * 255.0f, 1.0f) << x;
        }
    }
    simd::use_generic_path(false);
}

TEST(ShadingModels, BackFacesAreLitWithTheNormalAsItIs) {
    SurfaceUniforms u = uniforms();
    u.lights.count = 1;  // the light in front
    EXPECT_NEAR(shade<Shading::Lambert>(u, surface({0, 0, -1})).r, 0.8f * 0.1f, 1e-6f);  // not flipped: only ambient
}

// fragment_batch computes, lane by lane, the same bits as fragment: eight random fragments
// through each shading model, with and without texture and vertex colors.
template <Shading M, bool Textured, bool Colored>
void expect_batch_equals_scalar(const SurfaceUniforms& u) {
    using S = SurfaceShader<M, Textured, Colored>;
    constexpr int N = kVaryingCount<typename S::Varyings>;
    std::mt19937 rng(static_cast<unsigned>(M) * 4 + Textured * 2 + Colored);
    std::uniform_real_distribution<float> val(-1.5f, 1.5f);
    const S shader{&u};
    for (int trial = 0; trial < 200; ++trial) {
        std::array<simd::f8, N> in;
        simd::f8 z;
        for (int l = 0; l < simd::kLanes; ++l) {
            for (auto& v : in) v[l] = val(rng);
            z[l] = 0.5f + 0.3f * val(rng);
        }
        std::array<simd::f8, 4> batch;
        shader.fragment_batch(in, z, true, batch);
        if constexpr (PairShader<S>) {  // two rows of quads at once: each as fragment_batch gives it
            std::array<simd::f8, N> below;
            for (int l = 0; l < simd::kLanes; ++l)
                for (auto& v : below) v[l] = val(rng);
            for (size_t k = 0; k < 4; ++k)  // (the quads' derivatives, but now and then not)
                below[size_t(S::Varyings::kUvDerivativesAt) + k] = in[size_t(S::Varyings::kUvDerivativesAt) + k] * (trial % 7 == 0 ? 0.5f : 1.0f);
            std::array<simd::f8, 4> rows[2], alone;
            shader.fragment_pair(in, below, z, z + 0.1f, true, rows[0], rows[1]);
            shader.fragment_batch(below, z + 0.1f, true, alone);
            for (int l = 0; l < simd::kLanes; ++l)
                for (size_t ch = 0; ch < 4; ++ch) {
                    ASSERT_EQ(std::bit_cast<uint32_t>(rows[0][ch][l]), std::bit_cast<uint32_t>(batch[ch][l])) << "model " << int(M) << " first row";
                    ASSERT_EQ(std::bit_cast<uint32_t>(rows[1][ch][l]), std::bit_cast<uint32_t>(alone[ch][l])) << "model " << int(M) << " second row";
                }
            if constexpr (FourShader<S>) {  // and two such pairs: the first as above, the second as its own pair gives it
                std::array<simd::f8, N> next[2];
                for (auto& g : next)
                    for (int l = 0; l < simd::kLanes; ++l)
                        for (auto& v : g) v[l] = val(rng);
                for (size_t k = 0; k < 4; ++k) next[1][size_t(S::Varyings::kUvDerivativesAt) + k] = next[0][size_t(S::Varyings::kUvDerivativesAt) + k];
                const std::array<simd::f8, N> block_in[4] = {in, below, next[0], next[1]};
                const simd::f8 zs[4] = {z, z + 0.1f, z + 0.2f, z + 0.3f};
                std::array<simd::f8, 4> block[4], pair[2];
                shader.fragment_four(block_in, zs, true, block);
                shader.fragment_pair(next[0], next[1], zs[2], zs[3], true, pair[0], pair[1]);
                const std::array<simd::f8, 4>* want[4] = {&rows[0], &rows[1], &pair[0], &pair[1]};
                for (size_t g = 0; g < 4; ++g)
                    for (int l = 0; l < simd::kLanes; ++l)
                        for (size_t ch = 0; ch < 4; ++ch)
                            ASSERT_EQ(std::bit_cast<uint32_t>(block[g][ch][l]), std::bit_cast<uint32_t>((*want[g])[ch][l])) << "model " << int(M) << " group " << g;
            }
        }
        for (int l = 0; l < simd::kLanes; ++l) {
            std::array<float, size_t(N)> lane;
            for (size_t k = 0; k < size_t(N); ++k) lane[k] = in[k][l];
            glm::vec4 scalar;
            shader.fragment(from_array<typename S::Varyings>(lane), FragCoord{0, 0, z[l], true}, scalar);
            for (int ch = 0; ch < 4; ++ch)
                ASSERT_EQ(std::bit_cast<uint32_t>(batch[size_t(ch)][l]), std::bit_cast<uint32_t>(scalar[ch]))
                    << "model " << int(M) << " textured " << Textured << " colored " << Colored << " lane " << l << " channel " << ch;
        }
    }
}

TEST(ShadingModels, EightFragmentsAtOnceEqualOneAtATime) {
    SurfaceUniforms u = uniforms();
    u.lights.to_light[1] = glm::normalize(glm::vec3(0.3f, 1, 0.2f));
    Image img(5, 3);
    for (int i = 0; i < 15; ++i) img.pixels[size_t(i)] = {uint8_t(17 * i), uint8_t(255 - 9 * i), uint8_t(40 + 7 * i), uint8_t(200 + 3 * i)};
    const Texture texture(img);
    u.texture = &texture;
    for (Filter f : {Filter::Nearest, Filter::Bilinear})
        for (Wrap w : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror, Wrap::Border})
            for (MipFilter m : {MipFilter::None, MipFilter::Nearest, MipFilter::Linear}) {
                u.sampler = Sampler::plain(f, w);
                u.sampler.mip = m;
                u.sampler.border = glm::vec4(0.2f, 0.4f, 0.6f, 0.8f);
                expect_batch_equals_scalar<Shading::Unlit, true, true>(u);
                expect_batch_equals_scalar<Shading::BlinnPhong, true, false>(u);
            }
    // Point and spot lights and Phong.
    PositionalLight lights[2];
    lights[0].position = glm::vec3(0.5f, 1.0f, 2.0f);
    lights[0].color = glm::vec3(2.0f, 1.5f, 1.0f);
    lights[0].inv_range2 = 0.2f;
    lights[1].position = glm::vec3(-1.0f, 0.5f, 1.0f);
    lights[1].color = glm::vec3(1.0f, 2.0f, 3.0f);
    lights[1].spot = true;
    lights[1].spot_direction = glm::normalize(glm::vec3(0.5f, -0.2f, -1.0f));
    lights[1].cone_scale = 4.0f;
    lights[1].cone_offset = -3.2f;
    u.lights.positional = lights;
    u.lights.positional_count = 2;
    u.sampler = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
    expect_batch_equals_scalar<Shading::Phong, true, true>(u);
    expect_batch_equals_scalar<Shading::Phong, false, false>(u);
    expect_batch_equals_scalar<Shading::BlinnPhong, false, true>(u);
    // pbr, with every map and without the base color texture.
    u.metallic = 0.7f, u.roughness = 0.6f, u.occlusion_strength = 0.5f;
    u.emissive = glm::vec3(0.2f, 0.1f, 0.05f);
    u.metallic_roughness_texture = u.occlusion_texture = u.emissive_texture = &texture;
    expect_batch_equals_scalar<Shading::Pbr, true, true>(u);
    u.texture = nullptr;
    expect_batch_equals_scalar<Shading::Pbr, true, false>(u);
    u.texture = &texture;
    u.metallic_roughness_texture = u.occlusion_texture = u.emissive_texture = nullptr;
    expect_batch_equals_scalar<Shading::Pbr, false, true>(u);
    u.has_specular = false;
    expect_batch_equals_scalar<Shading::BlinnPhong, true, false>(u);
    u.has_specular = true;
    u.lights.positional_count = 0;
    u.shininess = 7.5f;  // not a whole number: powf per lane
    expect_batch_equals_scalar<Shading::BlinnPhong, false, true>(u);
    u.shininess = 16.0f;
    expect_batch_equals_scalar<Shading::Unlit, false, false>(u);
    expect_batch_equals_scalar<Shading::Flat, false, true>(u);
    expect_batch_equals_scalar<Shading::Gouraud, true, true>(u);
    expect_batch_equals_scalar<Shading::Lambert, false, false>(u);
    expect_batch_equals_scalar<Shading::Lambert, true, true>(u);
    expect_batch_equals_scalar<Shading::BlinnPhong, false, false>(u);
    expect_batch_equals_scalar<Shading::Normals, false, false>(u);
    expect_batch_equals_scalar<Shading::Depth, false, false>(u);
}

namespace {

// Vertex processing of `in` with the shader's vertex_lanes (the AVX2 path) and with vertex()
// one vertex at a time (the generic path): the same varyings and clip positions, bit for bit.
template <Shading M, bool Textured, bool Colored>
void expect_vertex_lanes_equal_vertex(const SurfaceUniforms& u, const std::vector<MeshVertex>& in) {
    using S = SurfaceShader<M, Textured, Colored>;
    static_assert(LaneVertexShader<S>);
    constexpr int N = kVaryingCount<typename S::Varyings>;
    const ClipPlanes planes = ClipPlanes::for_viewport(320, 240);
    std::vector<ShadedVertex<N>> lanes(in.size()), one(in.size());
    std::vector<ClipInfo> lanes_clip(in.size()), one_clip(in.size());
    process_vertices<true>(S{&u}, std::span<const MeshVertex>(in), 0, in.size(), planes, Viewport{320, 240}, std::span(lanes), std::span(lanes_clip));
    process_vertices<false>(S{&u}, std::span<const MeshVertex>(in), 0, in.size(), planes, Viewport{320, 240}, std::span(one), std::span(one_clip));
    for (size_t i = 0; i < in.size(); ++i) {
        EXPECT_EQ(std::memcmp(lanes[i].var.data(), one[i].var.data(), sizeof(one[i].var)), 0) << "varyings of vertex " << i << ", model " << int(M);
        EXPECT_EQ(std::memcmp(&lanes_clip[i].position, &one_clip[i].position, sizeof(glm::vec4)), 0) << "clip position of vertex " << i;
    }
}

}  // namespace

// The surface shaders' vertex() for eight vertices at once gives vertex()'s bits for every
// kind of varying: world position, normal, texture coordinates (with their derivatives' zero
// slots), vertex color, and none (one unused float); varying counts 1, 3, 6, 7 and 16, so that
// the last four floats of a vertex go out as 1, 2, 3 or 4. Gouraud (lighting per vertex) and
// tangents keep to vertex().
TEST(ShadingModels, VertexLanesSameAsVertex) {
    if (!simd::wide_path_runs()) GTEST_SKIP() << "no AVX2 on this machine";
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> r(-2.0f, 2.0f);
    SurfaceUniforms u = uniforms();
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) u.model[c][k] = r(rng), u.mvp[c][k] = r(rng);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) u.normal_matrix[c][k] = r(rng);
    std::vector<MeshVertex> in(45);  // five groups of eight and five left over
    for (MeshVertex& v : in)
        v = {glm::vec3(r(rng), r(rng), r(rng)) * 10.0f, glm::vec3(r(rng), r(rng), r(rng)), glm::vec2(r(rng), r(rng)), glm::vec4(r(rng), r(rng), r(rng), r(rng))};
    expect_vertex_lanes_equal_vertex<Shading::BlinnPhong, false, false>(u, in);  // world, normal: 6
    expect_vertex_lanes_equal_vertex<Shading::Pbr, true, true>(u, in);           // all but tangents: 16
    expect_vertex_lanes_equal_vertex<Shading::Unlit, true, false>(u, in);        // uv and derivatives: 6
    expect_vertex_lanes_equal_vertex<Shading::Lambert, false, true>(u, in);      // normal, color: 7
    expect_vertex_lanes_equal_vertex<Shading::Normals, false, false>(u, in);     // normal: 3
    expect_vertex_lanes_equal_vertex<Shading::Depth, false, false>(u, in);       // none: 1
    static_assert(!LaneVertexShader<SurfaceShader<Shading::Gouraud, false, false>>);
    static_assert(!LaneVertexShader<SurfaceShader<Shading::Pbr, true, false, true>>);
}
