// The library's front door: a Context draws primitives into a Framebuffer, stage by stage.
//
//   Framebuffer fb(640, 480);
//   Context ctx(fb);
//   ctx.clear(glm::vec4(0, 0, 0, 1));
//   ctx.state.cull = CullMode::None;
//   ctx.draw(Topology::Triangles, my_shader, vertices, indices);
//   Image picture = fb.read_pixels();
//
// vertex processing -> primitive assembly -> clipping -> perspective divide & viewport ->
// culling & triangle setup -> rasterization -> fragment shading -> output merge -> resolve.
#pragma once
#include <span>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/clipping.h"
#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/line_rasterization.h"
#include "softraster/pipeline/primitive_assembly.h"
#include "softraster/pipeline/vertex_processing.h"
#include "softraster/render_state.h"

namespace softraster {

// Calls f.template operator()<Samples, Blend>() with the framebuffer's sample count and the
// state's blend mode as compile-time constants, so inner loops never branch on them.
template <class F>
void dispatch_samples_blend(int samples, BlendMode blend, F&& f) {
    auto with_samples = [&]<BlendMode B>() {
        if (samples == 4) f.template operator()<4, B>();
        else f.template operator()<1, B>();
    };
    switch (blend) {
        case BlendMode::Opaque: with_samples.template operator()<BlendMode::Opaque>(); break;
        case BlendMode::Alpha: with_samples.template operator()<BlendMode::Alpha>(); break;
        case BlendMode::Additive: with_samples.template operator()<BlendMode::Additive>(); break;
    }
}

class Context {
public:
    explicit Context(Framebuffer& fb) : fb_(fb) {}

    RenderState state;

    void clear(const glm::vec4& color, float depth = 1.0f) {
        fb_.clear_color(color);
        fb_.clear_depth(depth);
    }
    Framebuffer& framebuffer() { return fb_; }

    // Draws `indices` (three per triangle, two per line, one per point) into the framebuffer.
    // Throws std::out_of_range for an index past the end of `vertices`.
    template <Shader S>
    void draw(Topology topology, const S& shader, std::span<const typename S::Vertex> vertices,
              std::span<const uint32_t> indices) {
        validate_indices(indices, vertices.size(), topology);
        constexpr int N = kVaryingCount<typename S::Varyings>;
        std::vector<ClipVertex<N>> post;
        process_vertices(shader, vertices, post);
        dispatch_samples_blend(fb_.samples(), state.blend, [&]<int Samples, BlendMode B>() {
            switch (topology) {
                case Topology::Triangles: draw_triangles<Samples, B>(shader, post, indices); break;
                case Topology::Lines: draw_lines<Samples, B>(shader, post, indices); break;
                case Topology::Points: draw_points<Samples, B>(shader, post, indices); break;
            }
        });
    }

private:
    Rect full_rect() const { return {0, 0, fb_.width(), fb_.height()}; }
    Viewport viewport() const { return {fb_.width(), fb_.height()}; }

    template <int Samples, BlendMode B, Shader S, int N>
    void draw_triangles(const S& shader, const std::vector<ClipVertex<N>>& post, std::span<const uint32_t> indices) {
        const ClipPlanes planes = ClipPlanes::for_viewport(fb_.width(), fb_.height());
        const Rect rect = full_rect();
        TriangleSetup<N> setup;
        auto emit = [&](const ClipVertex<N>& a, const ClipVertex<N>& b, const ClipVertex<N>& c) {
            WindowVertex<N> wa, wb, wc;
            if (!to_window(a, viewport(), wa) || !to_window(b, viewport(), wb) || !to_window(c, viewport(), wc)) return;
            if (!setup_triangle(wa, wb, wc, state.cull, state.front_face, rect, setup)) return;
            draw_triangle<Samples, B>(shader, state, fb_, setup, rect);
        };
        ClipPolygon<N> poly;
        for (size_t i = 0; i + 2 < indices.size(); i += 3) {
            const ClipVertex<N>& a = post[indices[i]];
            const ClipVertex<N>& b = post[indices[i + 1]];
            const ClipVertex<N>& c = post[indices[i + 2]];
            if (!is_finite(a.position) || !is_finite(b.position) || !is_finite(c.position)) continue;
            const unsigned ca = planes.outcode(a.position), cb = planes.outcode(b.position),
                           cc = planes.outcode(c.position);
            if (ca & cb & cc) continue;  // all outside one plane
            if ((ca | cb | cc) == 0) {
                emit(a, b, c);
                continue;
            }
            const int n = clip_triangle(a, b, c, planes, ca | cb | cc, poly);
            for (int k = 1; k + 1 < n; ++k) emit(poly.v[0], poly.v[size_t(k)], poly.v[size_t(k + 1)]);
        }
    }

    template <int Samples, BlendMode B, Shader S, int N>
    void draw_lines(const S& shader, const std::vector<ClipVertex<N>>& post, std::span<const uint32_t> indices) {
        using V = typename S::Varyings;
        const ClipPlanes planes = ClipPlanes::frustum();
        for (size_t i = 0; i + 1 < indices.size(); i += 2) {
            ClipVertex<N> a = post[indices[i]], b = post[indices[i + 1]];
            if (!is_finite(a.position) || !is_finite(b.position) || !clip_line(a, b, planes)) continue;
            WindowVertex<N> wa, wb;
            if (!to_window(a, viewport(), wa) || !to_window(b, viewport(), wb)) continue;
            rasterize_line(wa, wb, full_rect(), [&](int x, int y, float z, float t) {
                const std::array<float, Samples> zs = filled<Samples>(z);
                shade_fragment<Samples, B>(shader, state, fb_, x, y, all_samples<Samples>(), zs.data(), z, true, [&] {
                    std::array<float, N> v;
                    for (size_t k = 0; k < size_t(N); ++k) v[k] = wa.var[k] + t * (wb.var[k] - wa.var[k]);
                    return from_array<V>(v);
                });
            });
        }
    }

    template <int Samples, BlendMode B, Shader S, int N>
    void draw_points(const S& shader, const std::vector<ClipVertex<N>>& post, std::span<const uint32_t> indices) {
        using V = typename S::Varyings;
        const ClipPlanes planes = ClipPlanes::frustum();
        for (uint32_t index : indices) {
            const ClipVertex<N>& p = post[index];
            if (!is_finite(p.position) || planes.outcode(p.position) != 0) continue;
            WindowVertex<N> wp;
            if (!to_window(p, viewport(), wp)) continue;
            rasterize_point(wp, full_rect(), [&](int x, int y, float z) {
                const std::array<float, Samples> zs = filled<Samples>(z);
                shade_fragment<Samples, B>(shader, state, fb_, x, y, all_samples<Samples>(), zs.data(), z, true,
                                           [&] { return from_array<V>(wp.var); });
            });
        }
    }

    template <int Samples>
    static constexpr unsigned all_samples() { return (1u << Samples) - 1; }
    template <int Samples>
    static std::array<float, Samples> filled(float z) {
        std::array<float, Samples> a;
        a.fill(z);
        return a;
    }

    Framebuffer& fb_;
};

}  // namespace softraster
