// Stage 12, output merge: the parts compiled once for every shader and back end (see
// output_merge.h and fragment_shading.h), each in both CPU paths' copies (simd.h).
#include <array>
#include <cstdint>

#include "softraster/pipeline/fragment_shading.h"
#include "softraster/pipeline/output_merge.h"

namespace softraster {
namespace {

// sf and df below are written for every group g < n before they are read; GCC cannot follow
// that through the switches and warns. Zeroing them instead costs a memset per row, 10% of a
// blend-heavy frame.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
inline void blend_row_body(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups) {
    using simd::i8;
    constexpr size_t kMax = RowGroups::kMax;
    const size_t n = size_t(groups.count);
    // Channel-planar copies: s[c][g], d[c][g], and the constant's channels as vectors.
    std::array<std::array<i8, kMax>, 4> s, d, out;
    std::array<i8, kMax> old;
    for (size_t g = 0; g < n; ++g) {
        old[g] = simd::load_group<i8>(row, groups.x[g], width);
        for (size_t c = 0; c < 4; ++c) {
            s[c][g] = (groups.color[g] >> int(8 * c)) & 255;
            d[c][g] = (old[g] >> int(8 * c)) & 255;
        }
    }
    const std::array<i8, 4> k{simd::splat_i(b.constant.r), simd::splat_i(b.constant.g), simd::splat_i(b.constant.b),
                              simd::splat_i(b.constant.a)};
    std::array<i8, kMax> sf, df;
    for (size_t c = 0; c < 4; ++c) {
        if (!(b.color_mask & (1u << c))) {
            out[c] = d[c];
            continue;
        }
        const bool alpha = c == 3;
        auto factors = [&](BlendFactor f, std::array<i8, kMax>& into) {
            with_blend_factor(f, [&]<BlendFactor F>() {
                for (size_t g = 0; g < n; ++g)
                    into[g] = blend_factor<i8>(F, {s[0][g], s[1][g], s[2][g], s[3][g]}, {d[0][g], d[1][g], d[2][g], d[3][g]}, k, c);
            });
        };
        factors(alpha ? b.eq.src_alpha : b.eq.src_rgb, sf);
        factors(alpha ? b.eq.dst_alpha : b.eq.dst_rgb, df);
        with_blend_equation(alpha ? b.eq.alpha : b.eq.rgb, [&]<BlendEquation E>() {
            for (size_t g = 0; g < n; ++g) out[c][g] = blend_channel<i8>(E, s[c][g], sf[g], d[c][g], df[g]);
        });
    }
    for (size_t g = 0; g < n; ++g) {
        const i8 packed = out[0][g] | (out[1][g] << 8) | (out[2][g] << 16) | (out[3][g] << 24);
        simd::store_group(row, groups.x[g], width, simd::select(groups.write[g], packed, old[g]));
    }
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

template <bool Wide, bool Blended>
inline void merge_groups(const BlendSettings& settings, Framebuffer& fb, const GroupPlaces& p, const simd::i8* pass) {
    // Locals, not references: a color store may alias anything a reference reaches, which
    // would then be loaded again for every group.
    const BlendSettings blend = settings;
    const int width = fb.width(), count = p.count;
    Rgba8* const color = fb.color_plane();
    const size_t row_stride = fb.sample_index(0, 1);
    auto color_row = [&](int y) { return color + size_t(y) * row_stride; };
    if constexpr (!Blended) {
        // Opaque: each group's pixels as the framebuffer stores them, the color space chosen
        // once per batch rather than per group.
        simd::i8 packed[GroupPlaces::kCapacity];
        quantize_pack_groups<Wide>(p.rgba, count, blend.color_space, packed);
        for (int g = 0; g < count; ++g) {
            Rgba8* const row = color_row(p.y[g]);
            simd::store_group(row, p.x[g], width, simd::select(pass[g], packed[g], simd::load_group<simd::i8>(row, p.x[g], width)));
        }
        return;
    } else {
        if (blend.mode == BlendMode::Custom) {
            RowGroups row;
            int row_y = -1;
            for (int g = 0; g < count; ++g) {
                if (row.count > 0 && (p.y[g] != row_y || row.count == RowGroups::kMax))
                    blend_row_body(blend, color_row(row_y), width, row), row.count = 0;
                row_y = p.y[g];
                simd::i8 packed;
                quantize_pack_rgba8<Wide>(p.rgba[g], packed);
                row.add(p.x[g], pass[g], packed);
            }
            if (row.count > 0) blend_row_body(blend, color_row(row_y), width, row);
            return;
        }
        for (int g = 0; g < count; ++g) blend_group<Blended>(blend, color_row(p.y[g]), p.x[g], width, pass[g], p.rgba[g]);
    }
}

}  // namespace

SOFTRASTER_AVX2_TARGET void blend_row_wide(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups) {
    blend_row_body(b, row, width, groups);
}
void blend_row_generic(const BlendSettings& b, Rgba8* row, int width, const RowGroups& groups) { blend_row_body(b, row, width, groups); }

template <bool Blended>
SOFTRASTER_AVX2_TARGET void merge_groups_wide(const BlendSettings& blend, Framebuffer& fb, const GroupPlaces& p, const simd::i8* pass) {
    merge_groups<SOFTRASTER_HAS_AVX2_PATH, Blended>(blend, fb, p, pass);
}
template <bool Blended>
void merge_groups_generic(const BlendSettings& blend, Framebuffer& fb, const GroupPlaces& p, const simd::i8* pass) {
    merge_groups<false, Blended>(blend, fb, p, pass);
}
template void merge_groups_wide<false>(const BlendSettings&, Framebuffer&, const GroupPlaces&, const simd::i8*);
template void merge_groups_wide<true>(const BlendSettings&, Framebuffer&, const GroupPlaces&, const simd::i8*);
template void merge_groups_generic<false>(const BlendSettings&, Framebuffer&, const GroupPlaces&, const simd::i8*);
template void merge_groups_generic<true>(const BlendSettings&, Framebuffer&, const GroupPlaces&, const simd::i8*);

}  // namespace softraster
