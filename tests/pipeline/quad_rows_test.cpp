// The tile loop shades a textured surface's groups two rows at a time (a row of 2x2 quads'
// first and second rows, fragment_pair; tile_back_end.h), and two such pairs side by
// side at a time where it can (fragment_four); the fragment queue's groups of small
// triangles go two at a time too (fragment_pair, shader_layout.h). That must not change the
// picture: random textured triangles, drawn by SurfaceShader and by the same shader with
// fragment_pair taken away (each row's groups on their own), give byte-identical color
// and depth, opaque and blended, for several depth functions and texture filters. The pairs
// are drawn by the library's compiled pipeline (record_surface_draw), so only the row-by-row
// shader is compiled here: one lit, textured and colored model, whose fragment_pair is
// every model's (SurfaceShader's shading after the lookup is the same code either way).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "softraster/context.h"
#include "softraster/framebuffer.h"
#include "softraster/shading/surface_shader.h"
#include "scene/record_surface_draw.h"
#include "test_support.h"

using namespace softraster;
using namespace softraster::test;

namespace {

constexpr int W = 211, H = 157;  // not a multiple of 8 or 64, odd

// S without fragment_pair: the tile loop then shades row by row.
template <class S>
struct RowByRow : S {
    template <class... A>
    void fragment_pair(A&&...) const = delete;
};
constexpr Shading kModel = Shading::Lambert;  // (lit, yet not so bright that the colors clip)
using Paired = SurfaceShader<kModel, true, true>;  // what record_surface_draw draws colored textured meshes with
static_assert(PairShader<Paired>);
static_assert(FourShader<Paired>);  // (and two pairs side by side, fragment_four: the pictures below cover both)
static_assert(!PairShader<RowByRow<Paired>>);
static_assert(!PairShader<SurfaceShader<Shading::Unlit, false, false>>);  // (untextured: nothing to share)

// 60 triangles across the picture at random depths and slants (the texture minified on
// some, magnified on others), some of them back-facing, some odd-sized slivers.
std::vector<MeshVertex> random_triangles() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<MeshVertex> v;
    for (int k = 0; k < 60; ++k) {
        const float cx = u(rng) * 2 - 1, cy = u(rng) * 2 - 1, size = k % 9 == 0 ? 0.05f : 0.3f + 0.9f * u(rng);
        const float uv_scale = k % 3 == 0 ? 40.0f : 2.0f * u(rng);
        const float z = -2.5f - 5.0f * u(rng), reach = -z / 2;  // x and y in [-reach, reach] fill the picture at depth z
        for (int c = 0; c < 3; ++c) {
            MeshVertex m;
            m.position = {reach * (cx + size * (u(rng) - 0.5f)), reach * (cy + size * (u(rng) - 0.5f)), z + 1.5f * (u(rng) - 0.5f)};
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

// paired: drawn by the library (pairs of quad rows); else row by row.
Picture draw_with(const SurfaceUniforms& uniforms, bool paired, bool blended, DepthFunc func) {
    Framebuffer fb(W, H);
    Context ctx(fb);
    ctx.clear(glm::vec4(0.1f, 0.2f, 0.3f, 1.0f), func == DepthFunc::Greater ? 0.0f : 1.0f);
    ctx.state.cull = CullMode::None;
    ctx.state.depth_func = func;
    ctx.state.blend = blended ? BlendMode::Alpha : BlendMode::Opaque;
    Mesh mesh;
    mesh.vertices = random_triangles();
    for (size_t k = 0; k < mesh.vertices.size(); ++k) mesh.indices.push_back(uint32_t(k));
    SceneRenderer::Draw d;  // (the recorded draw points at its uniforms until finish())
    if (paired) {
        d.mesh = &mesh;
        d.uniforms = uniforms;
        d.colored = true;
        record_surface_draw<kModel>(ctx, d);
    } else {
        ctx.draw_triangles(RowByRow<Paired>{{&uniforms}}, std::span<const MeshVertex>(mesh.vertices), mesh.indices);
    }
    ctx.finish();
    const Image img = fb.read_pixels();
    Picture p;
    for (const Rgba8& c : img.pixels) p.color.insert(p.color.end(), {c.r, c.g, c.b, c.a});
    p.depth.assign(fb.depth_data(), fb.depth_data() + size_t(W) * H);
    return p;
}

void expect_same_picture(const SurfaceUniforms& uniforms, const std::string& what) {
    for (bool blended : {false, true})
        for (DepthFunc func : {DepthFunc::Less, DepthFunc::Greater, DepthFunc::Always}) {
            const Picture rows = draw_with(uniforms, true, blended, func), apart = draw_with(uniforms, false, blended, func);
            const float cleared = func == DepthFunc::Greater ? 0.0f : 1.0f;
            const auto drawn = std::count_if(rows.depth.begin(), rows.depth.end(), [&](float d) { return d != cleared; });
            EXPECT_GT(drawn, W * H / 3) << what;  // (the triangles cover about half the picture: the test compares something)
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
    // A perspective projection (near 1, far 10, the picture 4 units across at z = -4), so
    // depths vary and the texture is perspective-correct.
    u.mvp[0][0] = u.mvp[1][1] = 2.0f;
    u.mvp[2][2] = -11.0f / 9.0f, u.mvp[3][2] = -20.0f / 9.0f;
    u.mvp[2][3] = -1.0f, u.mvp[3][3] = 0.0f;
    u.lights.ambient = glm::vec3(0.3f);
    u.lights.count = 1;
    u.lights.to_light[0] = glm::vec3(0, 0, 1);
    u.lights.color[0] = glm::vec3(0.7f);
    u.texture = &texture;
    for (MipFilter mip : {MipFilter::Linear, MipFilter::Nearest, MipFilter::None}) {
        u.sampler = Sampler::plain(Filter::Bilinear, Wrap::Repeat);
        u.sampler.mip = mip;
        expect_same_picture(u, "mip " + std::to_string(int(mip)));
    }
    u.sampler = Sampler::plain(Filter::Bilinear, Wrap::Clamp);  // (not the common lookup: each row's sample8)
    u.sampler.mip = MipFilter::Linear;
    expect_same_picture(u, "clamp");
}
