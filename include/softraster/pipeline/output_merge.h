// Stage 12, output merge: blending and the color write (the depth test before it is
// depth_stencil.h).
//
// Color is stored as 8-bit RGBA. Blending follows the spec's formulas on the stored 8-bit
// destination, in 8-bit fixed point as llvmpipe and GPUs do it for RGBA8 targets: the source
// is clamped and quantized to 8 bits, each product rounded to nearest, sums saturated:
//   alpha:    rgb = s.rgb s.a + d.rgb (1 - s.a),  a = s.a + d.a (1 - s.a)
//   additive: rgb = s.rgb s.a + d.rgb,            a = d.a
// (Float arithmetic quantized once differs by one level here and there; over many layers
// those differences add up against the reference.)
//
// An sRGB framebuffer (framebuffer.h) stores r, g, b encoded (srgb.h): an opaque fragment's
// color is encoded as it is stored, and blending happens in linear light, in float
// (blend_linear below; those draws take the general back end, see needs_general_back_end).
#pragma once
#include <algorithm>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstring>
#include <type_traits>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/pipeline_types.h"
#include "softraster/pipeline/simd.h"
#include "softraster/render_state.h"
#include "softraster/srgb_avx512.h"

#if SOFTRASTER_HAS_AVX2_PATH
#include <immintrin.h>
#endif

namespace softraster {

// x * y / 255 for 8-bit x, y, rounded to nearest: the exact unorm8 product that GPUs and
// llvmpipe use ((t + 128 + ((t + 128) >> 8)) >> 8 with t = x * y, Blinn 1995).
inline unsigned mul_unorm8(unsigned x, unsigned y) {
    const unsigned t = x * y + 128;
    return (t + (t >> 8)) >> 8;
}

inline simd::i8 mul_unorm8(simd::i8 x, simd::i8 y) {
    const simd::i8 t = x * y + 128;
    return (t + (t >> 8)) >> 8;
}

inline Rgba8 blend(BlendMode mode, const glm::vec4& src, Rgba8 dst) {
    const Rgba8 s = quantize_rgba8(src);  // clamps to [0, 1]
    auto sat = [](unsigned v) { return uint8_t(v > 255 ? 255 : v); };
    const unsigned a = s.a, inv_a = 255u - s.a;
    switch (mode) {
        case BlendMode::Opaque:
        case BlendMode::Custom: break;  // (Custom draws blend in the general back end)
        case BlendMode::Alpha:
            return {sat(mul_unorm8(s.r, a) + mul_unorm8(dst.r, inv_a)), sat(mul_unorm8(s.g, a) + mul_unorm8(dst.g, inv_a)),
                    sat(mul_unorm8(s.b, a) + mul_unorm8(dst.b, inv_a)), sat(a + mul_unorm8(dst.a, inv_a))};
        case BlendMode::Additive:
            return {sat(mul_unorm8(s.r, a) + dst.r), sat(mul_unorm8(s.g, a) + dst.g), sat(mul_unorm8(s.b, a) + dst.b), dst.a};
    }
    return s;
}

// ---- every GL blend equation and factor (the general back end, general_back_end.h)
//
// The same fixed-point arithmetic, per channel c of source s (quantized), destination d and
// constant k (quantized), all in 0..255: the factors are 0, 255, s_c, d_c, k_c, s_a, d_a, k_a
// or 255 minus one of them, and SRC_ALPHA_SATURATE min(s_a, 255 - d_a) (255 for alpha);
//   add: min(255, s*S + d*D)   subtract: max(0, s*S - d*D)   reverse subtract: max(0, d*D - s*S)
//   min: min(s, d)             max: max(s, d)   (no factors)
// with each product x*y the rounded mul_unorm8. The presets are instances of it.

// The draw's blend settings, ready for the per-fragment arithmetic.
struct BlendSettings {
    BlendMode mode;
    BlendEquationState eq;
    Rgba8 constant;
    uint8_t color_mask = 0xf;  // bits r, g, b, a
    bool replace = false;      // the source replaces every channel: no arithmetic needed
    ColorSpace color_space;    // the framebuffer's
    explicit BlendSettings(const RenderState& st, ColorSpace color = ColorSpace::Linear)
        : eq(st.blend == BlendMode::Custom ? st.blend_equation : blend_preset(st.blend)),
          constant(quantize_rgba8(eq.constant)),
          color_mask(st.color_write ? st.color_mask : 0),
          replace(st.blend == BlendMode::Opaque && color_mask == 0xf),
          color_space(color) {
        // A partial color mask takes the general arithmetic (blend_channels), which keeps
        // the masked channels; the presets' own paths write all four.
        mode = color_mask != 0 && color_mask != 0xf ? BlendMode::Custom : st.blend;
    }
    // Whether the draw blends (reads what it overwrites): the back ends choose the merge by it.
    bool blends() const { return mode != BlendMode::Opaque; }
};

// One channel's factor and result, for one pixel (T = int) or eight (T = simd::i8, lane by
// lane): the same code either way. (T = float: the linear-light factors of an sRGB
// framebuffer, on values in [0, 1].)
template <class T>
inline T blend_factor(BlendFactor f, const std::array<T, 4>& s, const std::array<T, 4>& d, const std::array<T, 4>& k, size_t c) {
    const T zero{};
    T one;
    if constexpr (std::is_same_v<T, float>) one = 1.0f;
    else one = zero + 255;
    switch (f) {
        case BlendFactor::Zero: return zero;
        case BlendFactor::One: return one;
        case BlendFactor::SrcColor: return s[c];
        case BlendFactor::OneMinusSrcColor: return one - s[c];
        case BlendFactor::DstColor: return d[c];
        case BlendFactor::OneMinusDstColor: return one - d[c];
        case BlendFactor::SrcAlpha: return s[3];
        case BlendFactor::OneMinusSrcAlpha: return one - s[3];
        case BlendFactor::DstAlpha: return d[3];
        case BlendFactor::OneMinusDstAlpha: return one - d[3];
        case BlendFactor::ConstantColor: return k[c];
        case BlendFactor::OneMinusConstantColor: return one - k[c];
        case BlendFactor::ConstantAlpha: return k[3];
        case BlendFactor::OneMinusConstantAlpha: return one - k[3];
        case BlendFactor::SrcAlphaSaturate: return c == 3 ? one : (s[3] < one - d[3] ? s[3] : one - d[3]);
    }
    return zero;
}

template <class T>
inline T blend_channel(BlendEquation e, T s, T sf, T d, T df) {
    const T zero{}, one = zero + 255;
    auto mul_unorm8 = [](T x, T y) {
        if constexpr (std::is_same_v<T, int>) return int(softraster::mul_unorm8(unsigned(x), unsigned(y)));
        else return softraster::mul_unorm8(x, y);
    };
    auto clamp = [&](T v) { return v < zero ? zero : (v > one ? one : v); };
    switch (e) {
        case BlendEquation::Add: return clamp(mul_unorm8(s, sf) + mul_unorm8(d, df));
        case BlendEquation::Subtract: return clamp(mul_unorm8(s, sf) - mul_unorm8(d, df));
        case BlendEquation::ReverseSubtract: return clamp(mul_unorm8(d, df) - mul_unorm8(s, sf));
        case BlendEquation::Min: return s < d ? s : d;
        case BlendEquation::Max: return s > d ? s : d;
    }
    return s;
}

// All four channels, under the color mask (a masked channel keeps d).
template <class T>
inline std::array<T, 4> blend_channels(const BlendSettings& b, const std::array<T, 4>& s, const std::array<T, 4>& d,
                                       const std::array<T, 4>& k) {
    std::array<T, 4> out;
    for (size_t c = 0; c < 4; ++c) {
        if (!(b.color_mask & (1u << c))) {
            out[c] = d[c];
            continue;
        }
        const bool alpha = c == 3;
        const T sf = blend_factor(alpha ? b.eq.src_alpha : b.eq.src_rgb, s, d, k, c);
        const T df = blend_factor(alpha ? b.eq.dst_alpha : b.eq.dst_rgb, s, d, k, c);
        out[c] = blend_channel(alpha ? b.eq.alpha : b.eq.rgb, s[c], sf, d[c], df);
    }
    return out;
}

// Blending into an sRGB framebuffer, in linear light and in float (as llvmpipe does for
// SRGB8_ALPHA8 targets): source and constant clamped to [0, 1], the destination's r, g, b
// decoded and its alpha / 255, the factors and equations on those values, each result
// clamped to [0, 1] and stored as the framebuffer stores a color (masked channels keep d).
inline Rgba8 blend_linear(const BlendSettings& b, const glm::vec4& src, Rgba8 dst) {
    auto clamp01 = [](float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; };  // NaN -> 0
    const std::array<float, 4> s{clamp01(src.r), clamp01(src.g), clamp01(src.b), clamp01(src.a)};
    const std::array<float, 4> d{srgb::decode(dst.r), srgb::decode(dst.g), srgb::decode(dst.b), float(dst.a) * (1.0f / 255.0f)};
    const std::array<float, 4> k{clamp01(b.eq.constant.r), clamp01(b.eq.constant.g), clamp01(b.eq.constant.b), clamp01(b.eq.constant.a)};
    glm::vec4 out;
    for (size_t c = 0; c < 4; ++c) {
        const bool alpha = c == 3;
        const float sf = blend_factor(alpha ? b.eq.src_alpha : b.eq.src_rgb, s, d, k, c);
        const float df = blend_factor(alpha ? b.eq.dst_alpha : b.eq.dst_rgb, s, d, k, c);
        float v = s[c];
        switch (alpha ? b.eq.alpha : b.eq.rgb) {
            case BlendEquation::Add: v = s[c] * sf + d[c] * df; break;
            case BlendEquation::Subtract: v = s[c] * sf - d[c] * df; break;
            case BlendEquation::ReverseSubtract: v = d[c] * df - s[c] * sf; break;
            case BlendEquation::Min: v = s[c] < d[c] ? s[c] : d[c]; break;
            case BlendEquation::Max: v = s[c] > d[c] ? s[c] : d[c]; break;
        }
        out[int(c)] = clamp01(v);
    }
    Rgba8 q = quantize_rgba8(out, ColorSpace::Srgb);
    if (!(b.color_mask & 1u)) q.r = dst.r;
    if (!(b.color_mask & 2u)) q.g = dst.g;
    if (!(b.color_mask & 4u)) q.b = dst.b;
    if (!(b.color_mask & 8u)) q.a = dst.a;
    return q;
}

// The blended color of a fragment over dst, with the draw's color mask applied.
inline Rgba8 blend(const BlendSettings& b, const glm::vec4& src, Rgba8 dst) {
    if (b.color_space == ColorSpace::Srgb) return blend_linear(b, src, dst);
    const Rgba8 q = quantize_rgba8(src);
    const auto out = blend_channels<int>(b, {q.r, q.g, q.b, q.a}, {dst.r, dst.g, dst.b, dst.a},
                                         {b.constant.r, b.constant.g, b.constant.b, b.constant.a});
    return {uint8_t(out[0]), uint8_t(out[1]), uint8_t(out[2]), uint8_t(out[3])};
}

// Writes one shaded fragment's color to the samples in `mask` of a pixel. Blended: the
// draw blends (its mode is read here), the one blending fact the back end is compiled for,
// so that opaque draws never look at a blend mode.
template <int Samples, bool Blended>
inline void merge_fragment(const BlendSettings& b, Rgba8* color, unsigned mask, const glm::vec4& src) {
    if (Blended && b.mode == BlendMode::Custom) {
        for (int s = 0; s < Samples; ++s)
            if (mask & (1u << s)) color[s] = blend(b, src, color[s]);
        return;
    }
    if (!Blended) {
        const Rgba8 q = quantize_rgba8(src, b.color_space);
        for (int s = 0; s < Samples; ++s)
            if (mask & (1u << s)) color[s] = q;
        return;
    }
    for (int s = 0; s < Samples; ++s)
        if (mask & (1u << s)) color[s] = blend(b.mode, src, color[s]);
}

// ---- eight pixels of a row at once (see tile_back_end.h)


// Eight colors (r, g, b, a lanes) quantized to 8 bits per channel, packed as Rgba8. (The
// result by reference: a 32-byte vector returned by value crosses the AVX2 and generic
// copies' different calling conventions when the helper is not inlined, as in the
// sanitizer builds.) Wide: in the AVX2 copy, below.
template <bool Wide = false>
inline void quantize_pack_rgba8(const std::array<simd::f8, 4>& c, simd::i8& out) {
    using simd::quantize_unorm8;
    out = quantize_unorm8(c[0]) | (quantize_unorm8(c[1]) << 8) | (quantize_unorm8(c[2]) << 16) | (quantize_unorm8(c[3]) << 24);
}
#if SOFTRASTER_HAS_AVX2_PATH
// The same numbers with the clamps folded into the conversion: min(1, x) keeps a NaN (the
// second operand wins), x 255 + 0.5 truncates, and the packs saturate to 0..255, which is
// where a NaN (converted to INT_MIN), a negative x and clamp01's 0 all end. The packs leave
// each 128-bit half as r0..r3 g0..g3 b0..b3 a0..a3, and one byte shuffle makes pixels of it.
// Fewer instructions than clamping each channel first (docs/performance.md).
template <>
[[gnu::target("avx2")]] inline void quantize_pack_rgba8<true>(const std::array<simd::f8, 4>& c, simd::i8& out) {
    const __m256 one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f), half = _mm256_set1_ps(0.5f);
    __m256i q[4];
    for (size_t k = 0; k < 4; ++k) q[k] = _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(_mm256_min_ps(one, __m256(c[k])), scale), half));
    const __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(q[0], q[1]), _mm256_packs_epi32(q[2], q[3]));
    const __m256i to_pixels = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    out = simd::i8(_mm256_shuffle_epi8(bytes, to_pixels));
}
#endif
// The same as an sRGB framebuffer stores them (r, g, b encoded), with t = srgb::tables(),
// which a caller packing many groups reads once.
template <bool Wide = false>
inline void quantize_pack_srgb8(const srgb::Tables& t, const std::array<simd::f8, 4>& c, simd::i8& out) {
    simd::i8 r, g, b;
#if SOFTRASTER_HAS_AVX2_PATH
    if constexpr (Wide) {
        srgb::encode_avx2(t, c[0], r), srgb::encode_avx2(t, c[1], g), srgb::encode_avx2(t, c[2], b);
    } else
#endif
    {
        srgb::encode(t, c[0], r), srgb::encode(t, c[1], g), srgb::encode(t, c[2], b);
    }
    out = r | (g << 8) | (b << 16) | (simd::quantize_unorm8(c[3]) << 24);
}
// The same as a framebuffer of that color space stores them.
template <bool Wide = false>
inline void quantize_pack_rgba8(const std::array<simd::f8, 4>& c, ColorSpace space, simd::i8& out) {
    if (space == ColorSpace::Linear) return quantize_pack_rgba8<Wide>(c, out);
    quantize_pack_srgb8<Wide>(srgb::tables(), c, out);
}
// A batch's groups so (out[g] for rgba[g], g < count), the color space chosen once for the
// batch; an sRGB batch's on the AVX-512 copy where the CPU has one (srgb_avx512.h: no
// gathers).
template <bool Wide>
inline void quantize_pack_groups(const std::array<simd::f8, 4>* rgba, int count, ColorSpace space, simd::i8* out) {
    if (space == ColorSpace::Linear) {
        for (int g = 0; g < count; ++g) quantize_pack_rgba8<Wide>(rgba[g], out[g]);
        return;
    }
#if SOFTRASTER_HAS_AVX2_PATH
    if (Wide && simd::cpu_has_avx512()) return srgb::pack_groups_avx512(rgba, count, out);
#endif
    const srgb::Tables& t = srgb::tables();
    for (int g = 0; g < count; ++g) quantize_pack_srgb8<Wide>(t, rgba[g], out[g]);
}

// A source color of eight lanes in 8-bit: what blending reads of it (its channels times its
// alpha, mul_unorm8, its alpha and 1 - alpha), or for an opaque write the pixel as the
// framebuffer stores it (packed). Worked out apart from the merge, so that a color the same
// for a whole triangle is worked out once, not per group.
struct SourceUnorm8 {
    simd::i8 ra, ga, ba, a, inv_a, packed;
};
template <bool Blended>
inline SourceUnorm8 quantize_source(const BlendSettings& settings, const std::array<simd::f8, 4>& c) {
    SourceUnorm8 q{};
    if (!Blended || settings.mode == BlendMode::Opaque) {
        quantize_pack_rgba8(c, settings.color_space, q.packed);
    } else {
        q.a = simd::quantize_unorm8(c[3]);
        q.inv_a = 255 - q.a;
        q.ra = mul_unorm8(simd::quantize_unorm8(c[0]), q.a), q.ga = mul_unorm8(simd::quantize_unorm8(c[1]), q.a);
        q.ba = mul_unorm8(simd::quantize_unorm8(c[2]), q.a);
    }
    return q;
}

// Blends source s into the group of eight RGBA8 pixels from row[x] on (simd.h), where
// `write` is set: the same arithmetic as blend() above, lane by lane, for opaque draws and
// the presets (Custom draws blend a row at a time, blend_row below).
template <bool Blended>
inline void blend_group(const BlendSettings& settings, Rgba8* row, int x, int width, simd::i8 write, const SourceUnorm8& s) {
    using simd::i8;
    const BlendMode mode = settings.mode;
    const i8 old = simd::load_group<i8>(row, x, width);
    if (!Blended || mode == BlendMode::Opaque) {
        simd::store_group(row, x, width, simd::select(write, s.packed, old));
        return;
    }
    const i8 dr = old & 255, dg = (old >> 8) & 255, db = (old >> 16) & 255, da = (old >> 24) & 255;
    i8 r, g, b, a;
    if (mode == BlendMode::Alpha) {
        r = s.ra + mul_unorm8(dr, s.inv_a);
        g = s.ga + mul_unorm8(dg, s.inv_a);
        b = s.ba + mul_unorm8(db, s.inv_a);
        a = s.a + mul_unorm8(da, s.inv_a);
    } else {
        r = s.ra + dr;
        g = s.ga + dg;
        b = s.ba + db;
        a = da;
    }
    const i8 max = simd::splat_i(255);
    r = r > max ? max : r;
    g = g > max ? max : g;
    b = b > max ? max : b;
    a = a > max ? max : a;
    simd::store_group(row, x, width, simd::select(write, r | (g << 8) | (b << 16) | (a << 24), old));
}
// The same for colors c (r, g, b, a lanes).
template <bool Blended>
inline void blend_group(const BlendSettings& settings, Rgba8* row, int x, int width, simd::i8 write, const std::array<simd::f8, 4>& c) {
    blend_group<Blended>(settings, row, x, width, write, quantize_source<Blended>(settings, c));
}

// ---- every equation and factor, a row at a time
//
// Choosing a factor or an equation is a switch; taken per channel for each group of eight
// pixels, that is twelve jumps per group, and the choices never change within a draw. So a
// Custom draw's groups of a row (at most a tile's width) are shaded first, their colors kept
// here, and blended together: each switch then runs once per channel and row, around a loop
// over the groups (blend_factor and blend_channel with the choice a constant).

// The shaded groups of one row, waiting to be blended.
struct RowGroups {
    static constexpr int kMax = kTileSize / simd::kLanes;
    int count = 0;
    std::array<int, kMax> x;             // each group's first pixel
    std::array<simd::i8, kMax> color;    // packed RGBA8 (quantize_pack_rgba8)
    std::array<simd::i8, kMax> write;    // lanes to write
    void add(int at, simd::i8 lanes, simd::i8 packed) {
        x[size_t(count)] = at, write[size_t(count)] = lanes, color[size_t(count)] = packed;
        ++count;
    }
};

// Calls f.template operator()<F>() with the run-time factor (equation) as a constant.
template <class F>
inline void with_blend_factor(BlendFactor f, F&& fn) {
    switch (f) {
#define SOFTRASTER_FACTOR_CASE(name) \
    case BlendFactor::name: return fn.template operator()<BlendFactor::name>();
        SOFTRASTER_FACTOR_CASE(Zero) SOFTRASTER_FACTOR_CASE(One) SOFTRASTER_FACTOR_CASE(SrcColor)
        SOFTRASTER_FACTOR_CASE(OneMinusSrcColor) SOFTRASTER_FACTOR_CASE(DstColor) SOFTRASTER_FACTOR_CASE(OneMinusDstColor)
        SOFTRASTER_FACTOR_CASE(SrcAlpha) SOFTRASTER_FACTOR_CASE(OneMinusSrcAlpha) SOFTRASTER_FACTOR_CASE(DstAlpha)
        SOFTRASTER_FACTOR_CASE(OneMinusDstAlpha) SOFTRASTER_FACTOR_CASE(ConstantColor)
        SOFTRASTER_FACTOR_CASE(OneMinusConstantColor) SOFTRASTER_FACTOR_CASE(ConstantAlpha)
        SOFTRASTER_FACTOR_CASE(OneMinusConstantAlpha) SOFTRASTER_FACTOR_CASE(SrcAlphaSaturate)
#undef SOFTRASTER_FACTOR_CASE
    }
}
template <class F>
inline void with_blend_equation(BlendEquation e, F&& fn) {
    switch (e) {
        case BlendEquation::Add: return fn.template operator()<BlendEquation::Add>();
        case BlendEquation::Subtract: return fn.template operator()<BlendEquation::Subtract>();
        case BlendEquation::ReverseSubtract: return fn.template operator()<BlendEquation::ReverseSubtract>();
        case BlendEquation::Min: return fn.template operator()<BlendEquation::Min>();
        case BlendEquation::Max: return fn.template operator()<BlendEquation::Max>();
    }
}

// Blends the row's groups into `row` (of `width` pixels) with every equation and factor,
// under the color mask: the same bytes as blend(BlendSettings, ...) pixel by pixel. The
// same for every shader and back end, so compiled once (src/pipeline/output_merge.cpp), in
// each CPU path's copy (simd.h).
void blend_row_wide(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups);
void blend_row_generic(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups);
template <bool WideLanes>
inline void blend_row(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups) {
    if constexpr (WideLanes && SOFTRASTER_HAS_AVX2_PATH) blend_row_wide(b, row, width, groups);
    else blend_row_generic(b, row, width, groups);
}

}  // namespace softraster
