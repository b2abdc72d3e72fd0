// Stage 8, rasterization: which samples of which pixels a set-up triangle covers.
//
// The edge functions are affine in the pixel position, so along a row each is an arithmetic
// progression and the pixels inside it form one span, found by an integer division; the
// pixels of a row inside all three edges are the intersection of three spans. Pixel (x, y) is sampled
// at its center (x + 0.5, y + 0.5), or with 4x MSAA at the four positions of the spec's
// pattern; each sample is covered when E_i + bias_i >= 0 for all three edges.
#pragma once
#include <array>
#include <cstdint>

#include "softraster/pipeline/interpolation.h"
#include "softraster/pipeline/sample_pattern.h"
#include "softraster/pipeline/triangle_setup.h"

namespace softraster {

// One pixel the triangle touches: its covered samples and their depths.
template <int Samples>
struct CoveredPixel {
    int x = 0, y = 0;
    unsigned mask = 0;  // bit s set: sample s is covered
    std::array<float, Samples> z{};
};

// First k >= 0 with e + step * k >= 0, and first k at which it stops holding, for k in
// [0, n): the span of pixels (or samples) inside one edge along a row. Exact integers.
struct Span {
    int begin, end;
};
// Rows at most this many pixels wide test each pixel instead (small triangles).
inline constexpr int kNarrow = 16;
// The division (tens of cycles for 64 bits) only where the edge crosses the row: a row
// wholly on one side of it, as most rows of a big triangle are, is told by its last pixel.
inline Span edge_span(int64_t e, int64_t step, int n) {
    if (step == 0) return e >= 0 ? Span{0, n} : Span{0, 0};
    const int64_t last = e + step * (n - 1);
    if (step > 0) {  // inside from some k on: k >= ceil(-e / step)
        if (e >= 0) return {0, n};
        if (last < 0) return {n, n};
        const int64_t k = (-e + step - 1) / step;
        return {int(std::min<int64_t>(k, n)), n};
    }
    if (e < 0) return {0, 0};  // step < 0: inside up to k <= floor(e / -step)
    if (last >= 0) return {0, n};
    const int64_t k = e / -step + 1;
    return {0, int(std::min<int64_t>(k, n))};
}

// The edge functions (plus bias) at each sample position of the pixels of a row, from the
// row's first pixel: each sample's span of the row's pixels inside all three edges, and the
// step to the next row. Exact integers.
template <int Samples>
struct SampleRows {
    std::array<std::array<int64_t, 3>, Samples> e;  // E + bias at sample s of the row's first pixel
    std::array<int64_t, 3> step_x, step_y;          // one pixel right, one row down
    SampleRows(const TriangleEdges& t, int x, int y) {
        using P = SamplePattern<Samples>;
        for (size_t s = 0; s < size_t(Samples); ++s)
            for (size_t i = 0; i < 3; ++i)
                e[s][i] = t.edge(int(i), int64_t(x) * kSubpixelOne + P::x[s], int64_t(y) * kSubpixelOne + P::y[s]) + t.bias[i];
        for (size_t i = 0; i < 3; ++i) step_x[i] = t.A[i] * kSubpixelOne, step_y[i] = t.B[i] * kSubpixelOne;
    }
    // Sample s's covered pixels among the row's first n: [begin, end), empty if begin >= end.
    Span span(size_t s, int n) const {
        Span sp{0, n};
        for (size_t i = 0; i < 3; ++i) {
            const Span es = edge_span(e[s][i], step_x[i], n);
            sp = {std::max(sp.begin, es.begin), std::min(sp.end, es.end)};
        }
        return sp;
    }
    void next_row() {
        for (auto& se : e)
            for (size_t i = 0; i < 3; ++i) se[i] += step_y[i];
    }
};

// Calls on_pixel(const CoveredPixel<Samples>&) for every pixel of `rect` with coverage.
// Row by row: the edge functions give, for each sample position, the exact span of pixels
// inside all three edges (three integer divisions per row and sample), so the pixels in
// between need no test at all.
template <int Samples, class OnPixel>
void rasterize_triangle(const TriangleEdges& t, const Rect& rect, OnPixel&& on_pixel) {
    const int x0 = std::max(rect.x0, t.bounds.x0), x1 = std::min(rect.x1, t.bounds.x1);
    const int y0 = std::max(rect.y0, t.bounds.y0), y1 = std::min(rect.y1, t.bounds.y1);
    if (x0 >= x1 || y0 >= y1) return;
    const int n = x1 - x0;
    using P = SamplePattern<Samples>;
    SampleRows<Samples> rows(t, x0, y0);
    CoveredPixel<Samples> px;
    const float j0 = float(y0 - t.origin_y), i0 = float(x0 - t.origin_x);
    for (int y = y0; y < y1; ++y) {
        std::array<Span, Samples> spans{};
        std::array<std::array<int64_t, 3>, Samples> e = rows.e;  // for narrow rows: stepped per pixel
        int lo = 0, hi = n;
        if (n > kNarrow) {  // wide: exact spans by division
            lo = n, hi = 0;
            for (size_t s = 0; s < size_t(Samples); ++s) {
                spans[s] = rows.span(s, n);
                if (spans[s].begin < spans[s].end) lo = std::min(lo, spans[s].begin), hi = std::max(hi, spans[s].end);
            }
        }
        rows.next_row();
        const float j = j0 + float(y - y0);
        for (int k = lo; k < hi; ++k) {
            unsigned mask = 0;
            if (n > kNarrow) {
                for (size_t s = 0; s < size_t(Samples); ++s)
                    if (k >= spans[s].begin && k < spans[s].end) mask |= 1u << s;
            } else {  // narrow: a sign test per sample, cheaper than three 64-bit divisions
                for (size_t s = 0; s < size_t(Samples); ++s) {
                    if ((e[s][0] | e[s][1] | e[s][2]) >= 0) mask |= 1u << s;
                    for (size_t i = 0; i < 3; ++i) e[s][i] += rows.step_x[i];
                }
            }
            if (!mask) continue;
            px.x = x0 + k;
            px.y = y;
            px.mask = mask;
            const float i = i0 + float(k);
            for (size_t s = 0; s < size_t(Samples); ++s)
                px.z[s] = interpolate_depth(t, i + float(P::x[s] - 128) * (1.0f / 256.0f), j + float(P::y[s] - 128) * (1.0f / 256.0f));
            on_pixel(px);
        }
    }
}

// Single-sampled: calls on_span(y, x_begin, x_end) for each row's run of covered pixels
// (a triangle is convex, so a row's covered pixels are contiguous).
template <class OnSpan>
void rasterize_spans(const TriangleEdges& t, const Rect& rect, OnSpan&& on_span) {
    const int x0 = std::max(rect.x0, t.bounds.x0), x1 = std::min(rect.x1, t.bounds.x1);
    const int y0 = std::max(rect.y0, t.bounds.y0), y1 = std::min(rect.y1, t.bounds.y1);
    if (x0 >= x1 || y0 >= y1) return;
    const int n = x1 - x0;
    // (A local: on_span may store to memory that a reference to t could alias.)
    SampleRows<1> rows(t, x0, y0);  // at the pixels' centers
    for (int y = y0; y < y1; ++y) {
        int lo = 0, hi = n;
        if (n > kNarrow) {
            const Span sp = rows.span(0, n);
            lo = sp.begin, hi = sp.end;
        } else {  // narrow: walk to the first covered pixel, then to the first uncovered one
            std::array<int64_t, 3> e = rows.e[0];
            auto inside = [&] { return (e[0] | e[1] | e[2]) >= 0; };
            auto step = [&] {
                for (size_t i = 0; i < 3; ++i) e[i] += rows.step_x[i];
            };
            lo = 0;
            while (lo < n && !inside()) ++lo, step();
            hi = lo;
            while (hi < n && inside()) ++hi, step();
        }
        if (lo < hi) on_span(y, x0 + lo, x0 + hi);
        rows.next_row();
    }
}

}  // namespace softraster
