// The tile loop shades a textured surface's groups two rows at a time (a row of 2x2 quads'
// first and second rows, fragment_quad_rows; tile_back_end.h). That must not change the
// picture: random textured triangles, drawn by SurfaceShader and by the same shader with
// fragment_quad_rows taken away (each row's groups on their own), give byte-identical color
// and depth, opaque and blended, for several depth functions and texture filters.
#include <gtest/gtest.h>

#include <random>

#include "softraster/context.h"
#include "softraster/framebuffer.h"
#include "softraster/shading/surface_shader.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 211, H = 157;  // not a multiple of 8 or 64, odd

// S without fragment_quad_rows: the tile loop then shades row by row.
template <class S>
struct RowByRow : S {
    template <class... A>
    void fragment_quad_rows(A&&...) const = delete;
};
static_assert(QuadRowShader<SurfaceShader<Shading::Unlit, true, false>>);
static_assert(!QuadRowShader<RowByRow<SurfaceShader<Shading::Unlit, true, false>>>);
static_assert(!QuadRowShader<SurfaceShader<Shading::Unlit, false, false>>);  // (untextured: nothing to share)

// 60 triangles across the picture at random depths and slants (the texture minified on
// some, magnified on others), some of them back-facing, some odd-sized slivers.
std::vector<MeshVertex> random_triangles() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<MeshVertex> v;
    for (int k = 0; k < 60; ++k) {
        const float cx = u(rng) * 2 - 1, cy = u(rng) * 2 - 1, size = k % 9 == 0 ? 0.05f : 0.3f + 0.9f * u(rng);
        const float uv_scale = k % 3 == 0 ? 40.0f : 2.0f * u(rng);
        for (int c = 0; c < 3; ++c) {
            MeshVertex m;
            m.position = {cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), -2.0f - 6.0f * u(rng)};
            m.uv = {uv_scale * u(rng), uv_scale * u(rng)};
            m.color = {u(rng), u(rng), u(rng), 0.3f + 0.7f * u(rng)};
            v.push_back(m);
        }
    }
    return v;
}

struct Picture {
    std::vector<uint8_t> color;
    std::vector<float> depth;
};

template <class S>
Picture draw_with(const SurfaceUniforms& uniforms, bool blended, DepthFunc func) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0.1f, 0.2f, 0.3f, 1.0f), func == DepthFunc::Greater ? 0.0f : 1.0f);
    ctx.state.cull = CullMode::None;
    ctx.state.depth_func = func;
    ctx.state.blend = blended ? BlendMode::Alpha : BlendMode::Opaque;
    const std::vector<MeshVertex> v = random_triangles();
    std::vector<uint32_t> idx(v.size());
    for (size_t k = 0; k < idx.size(); ++k) idx[k] = uint32_t(k);
    S shader;
    shader.u = &uniforms;
    draw(ctx, shader, v, idx);
    const Image img = fb.read_pixels();
    Picture p;
    for (const Rgba8& c : img.pixels) p.color.insert(p.color.end(), {c.r, c.g, c.b, c.a});
    p.depth.assign(fb.depth_data(), fb.depth_data() + size_t(W) * H);
    return p;
}

template <class S>
void expect_same_picture(const SurfaceUniforms& uniforms, const std::string& what) {
    for (bool blended : {false, true})
        for (DepthFunc func : {DepthFunc::Less, DepthFunc::Greater, DepthFunc::Always}) {
            const Picture rows = draw_with<S>(uniforms, blended, func), apart = draw_with<RowByRow<S>>(uniforms, blended, func);
            EXPECT_TRUE(rows.color == apart.color) << what << " blended " << blended << " func " << int(func);
            EXPECT_TRUE(rows.depth == apart.depth) << what << " blended " << blended << " func " << int(func);
        }
}

}  // namespace

TEST(QuadRows, SamePictureAsRowByRow) {
    Image img(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) img.at(x, y) = {uint8_t(x * 4), uint8_t(y * 4), uint8_t((x ^ y) * 4), uint8_t(255 - x)};
    const Texture texture(img);
    SurfaceUniforms u;
    u.mvp = glm::mat4{1.0f};
    u.mvp[2][3] = -1.0f, u.mvp[3][3] = 0.0f;  // a perspective divide by -z, so the texture is perspective-correct
    u.lights.ambient = glm::vec3(0.3f);
    u.lights.count = 1;
    u.lights.to_light[0] = glm::vec3(0, 0, 1);
    u.lights.color[0] = glm::vec3(0.7f);
    u.texture = &texture;
    for (MipFilter mip : {MipFilter::Linear, MipFilter::Nearest, MipFilter::None}) {
        u.sampler = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
        u.sampler.mip = mip;
        expect_same_picture<SurfaceShader<Shading::Unlit, true, false>>(u, "unlit mip " + std::to_string(int(mip)));
    }
    u.sampler = Sampler::plain(Filter::Bilinear, Wrap::Clamp);  // (not the common lookup: each row's sample8)
    u.sampler.mip = MipFilter::Linear;
    expect_same_picture<SurfaceShader<Shading::Lambert, true, true>>(u, "lambert, clamp");
    u.sampler.wrap_s = u.sampler.wrap_t = Wrap::Repeat;
    expect_same_picture<SurfaceShader<Shading::BlinnPhong, true, true>>(u, "blinn-phong");
}
