// The eight-lane lookup (Texture::sample8) for any texture and sampler (the general body);
// the common case goes first to texture_uniform.cpp. The arithmetic: texture_lanes.h.
#include "texture_lanes.h"

namespace softraster {

using namespace lanes;

template <bool Wide, bool Srgb>
void Texture::sample_lanes(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    // Anisotropic filtering compiles to a copy of its own (Aniso), so that it costs the
    // other lookups nothing; so does the fixed-point filter (Fixed, texture.h "Precision").
    auto body = [&]<bool Aniso, bool Fixed, bool Pot>() {
        using simd::select, simd::splat, simd::splat_i, simd::to_float;
        // (Pot: both axes repeat, known here, so that no lookup asks which wrap mode.)
        const Wrap wrap_s = Pot ? Wrap::Repeat : s.wrap_s, wrap_t = Pot ? Wrap::Repeat : s.wrap_t;
        // Which level(s) and filter each lane takes (select_lod).
        i8 level0 = splat_i(0), level1 = splat_i(0), nearest = splat_i(s.mag == Filter::Nearest ? -1 : 0), probes = splat_i(1);
        f8 weight = splat(0.0f), axis_u = splat(0.0f), axis_v = splat(0.0f);
        if (s.uses_lod()) {
            f8 rx, ry;
            footprint_axes8(d.data(), float(width()), float(height()), rx, ry);
            f8 rho2 = select(rx > ry, rx, ry);
            const i8 minified = rho2 > 1.0f;
            nearest = select(minified, splat_i(s.min == Filter::Nearest ? -1 : 0), nearest);
            if constexpr (Aniso) {  // probe_count and the long axis, lane by lane
                const f8 rmin = select(rx > ry, ry, rx);
                probes = splat_i(1);
                for (int k = 1; k < s.max_anisotropy; ++k) probes = select(to_float(splat_i(k * k)) * rmin < rho2, probes + 1, probes);
                probes = select(minified, probes, splat_i(1));
                axis_u = select(rx > ry, d[0], d[2]), axis_v = select(rx > ry, d[1], d[3]);
                rho2 = rho2 / to_float(probes * probes);
            }
            const LaneLod lod = lane_lod<Wide>(rho2, minified, s.mip, levels() - 1);
            level0 = lod.level0, level1 = lod.level1, weight = lod.weight;
        }
        const bool two_levels = s.mip == MipFilter::Linear && simd::any(weight != 0.0f);
        auto lane_levels = [&](i8 level) {
            LaneLevels r;  // (not zeroed: every branch sets every number)
            if (!simd::any(level != level[0])) {  // one level for all (neighbouring quads mostly agree)
                const Level& l = levels_[size_t(level[0])];
                r.width = splat_i(l.width), r.height = splat_i(l.height), r.tiles_x = splat_i(l.tiles_x), r.offset = splat_i(l.offset);
                return r;
            }
            if (levels() <= 16) {  // a texture under 65536 texels a side: two table lookups per number
                const i8 high = level >= 8, index = level & 7;
                auto pick = [&](const std::array<int32_t, 16>& table) {
                    i8 low_half, high_half;
                    std::memcpy(&low_half, table.data(), sizeof(i8));
                    std::memcpy(&high_half, table.data() + 8, sizeof(i8));
                    return select(high, simd::permute(high_half, index), simd::permute(low_half, index));
                };
                r.width = pick(tables_.width), r.height = pick(tables_.height), r.tiles_x = pick(tables_.tiles_x), r.offset = pick(tables_.offset);
                return r;
            }
            r.width = r.height = r.tiles_x = r.offset = splat_i(0);
            for (int k = 0; k < simd::kLanes; ++k) {
                const Level& l = levels_[size_t(level[k])];
                r.width[k] = l.width, r.height[k] = l.height, r.tiles_x[k] = l.tiles_x, r.offset[k] = l.offset;
            }
            return r;
        };
        // sample_level: nearest lanes take the bilinear formula at x = u with weights 0, which
        // gives exactly the one texel (t * 1 + t' * 0 = t).
        const f8 half = select(nearest, splat(0.0f), splat(0.5f));
        // (The fixed-point filter's steps: 1/256 of a texel, 1/4096 for sRGB; texture.h "Precision".)
        constexpr int kBits = Texture::fraction_bits(Srgb), kOne = 1 << kBits;
        const i8 half_step = select(nearest, splat_i(0), splat_i(kOne / 2));  // (half a texel in those steps)
        const uint32_t* texels = this->texels();
        // (The table's address once: srgb::tables() is a call.)
        const uint32_t* decode = Srgb ? reinterpret_cast<const uint32_t*>(srgb::tables().decode.data()) : nullptr;
        const bool has_border = wrap_s == Wrap::Border || wrap_t == Wrap::Border;
        // The footprint's four texels, (ia, ja), (ib, ja), (ia, jb), (ib, jb), from the texel
        // below-left of the sample point, and which are the border color.
        auto footprint_indices = [&](const LaneLevels& l, const i8& i0, const i8& j0, i8 (&index)[4], i8 (&border)[4]) {
            const i8 ia = wrap_texel8<Pot>(i0, l.width, wrap_s), ib = wrap_texel8<Pot>(i0 + 1, l.width, wrap_s);
            const i8 ja = wrap_texel8<Pot>(j0, l.height, wrap_t), jb = wrap_texel8<Pot>(j0 + 1, l.height, wrap_t);
            const i8 is[4] = {ia, ib, ia, ib}, js[4] = {ja, ja, jb, jb};
            for (int t = 0; t < 4; ++t) {
                border[t] = (is[t] < 0) | (js[t] < 0);  // (never without a border wrap mode)
                const i8 at = tile_index8(l.offset, l.tiles_x, is[t], js[t]);
                index[t] = has_border ? select(border[t], splat_i(0), at) : at;
            }
        };
        auto footprint = [&](const LaneLevels& l, const i8& i0, const i8& j0, i8 (&texel)[4], i8 (&border)[4]) {
            i8 index[4];
            footprint_indices(l, i0, j0, index, border);
            for (int t = 0; t < 4; ++t) {
                if constexpr (Srgb) {  // (the float filter: a border color with an sRGB texture, which keeps no bytes)
                    for (int k = 0; k < simd::kLanes; ++k) texel[t][k] = int32_t(stored_bits(uint32_t(index[t][k])));
                } else {
                    gather<Wide>(texels, index[t], texel[t]);
                }
            }
        };
        // Repeat and clamp read the footprint from the tile's apron (texture.h): its lower-left
        // texel wrapped, the others at offsets 1, 5 and 6. Clamp at an edge, where both texels
        // of an axis are the edge texel, reads the edge texel alone: weight 0 on the other.
        const bool apron = wrap_s != Wrap::Mirror && wrap_t != Wrap::Mirror;
        auto apron_axis = [&](const i8& i0, const i8& n, Wrap w, i8& fraction) {
            if (w != Wrap::Clamp) return wrap_texel8<Pot>(i0, n, w);
            const i8 edge = (i0 < 0) | (i0 >= n - 1);
            fraction = select(edge, splat_i(0), fraction);
            return select(i0 < 0, splat_i(0), select(edge, n - 1, i0));
        };
        // One level's lookup: in fixed point (sample_level_fixed; a Fixed8 result) ...
        auto at_level_fixed = [&](const LaneLevels& l, const f8& ur, const f8& vr) {
            // The sample point in 1/256 texel steps (sample_level_fixed; sample_uniform takes
            // a power-of-two texture's from level 0's).
            const i8 x = floor_small8(ur * to_float(l.width) * float(kOne)) - half_step, y = floor_small8(vr * to_float(l.height) * float(kOne)) - half_step;
            i8 fx = select(nearest, splat_i(0), x & (kOne - 1)), fy = select(nearest, splat_i(0), y & (kOne - 1));
            if constexpr (Srgb) {  // texels decoded onto the fixed-point scale at load (fixed_texels)
                Fixed8 corner[4];
                if (apron) {
                    const i8 i0 = apron_axis(x >> kBits, l.width, wrap_s, fx), j0 = apron_axis(y >> kBits, l.height, wrap_t, fy);
                    load_footprints_fixed<Wide>(fixed_texels(), tile_index8(l.offset, l.tiles_x, i0, j0), corner);
                } else {
                    i8 index[4], border[4];
                    footprint_indices(l, x >> kBits, y >> kBits, index, border);
                    for (int t = 0; t < 4; ++t) gather_fixed<Wide>(fixed_texels(), index[t], corner[t]);
                }
                return bilinear_fixed<Wide, kBits>(corner, fx, fy);
            }
            i8 texel[4];
            if (apron) {
                const i8 i0 = apron_axis(x >> 8, l.width, wrap_s, fx), j0 = apron_axis(y >> 8, l.height, wrap_t, fy);
                load_footprints<Wide>(texels, tile_index8(l.offset, l.tiles_x, i0, j0), texel);
            } else {
                i8 border[4];
                footprint(l, x >> 8, y >> 8, texel, border);
            }
            return bilinear16<Wide>(texel, fx, fy);
        };
        // ... or in float (sample_level; four channels).
        auto at_level_float = [&](const LaneLevels& l, const f8& ur, const f8& vr, std::array<f8, 4>& out) {
            const f8 x = ur * to_float(l.width) - half, y = vr * to_float(l.height) - half;
            const i8 i0 = floor_small8(x), j0 = floor_small8(y);
            const f8 fx = select(nearest, splat(0.0f), x - to_float(i0)), fy = select(nearest, splat(0.0f), y - to_float(j0));
            i8 texel[4], border[4];
            footprint(l, i0, j0, texel, border);
            std::array<f8, 4> c[4];
            for (size_t t = 0; t < 4; ++t) {
                texel_channels<Wide, Srgb>(texel[t], decode, c[t]);
                if (has_border)
                    for (size_t k = 0; k < 4; ++k) c[t][k] = select(border[t], splat(s.border[int(k)]), c[t][k]);
            }
            bilinear_float(c, fx, fy, out);
        };
        // The lookup at (ur, vr) in the lanes' level(s), as floats.
        auto lookup_reduced = [&](const LaneLevels& levels0, const LaneLevels& levels1, const f8& ur, const f8& vr, std::array<f8, 4>& out) {
            if constexpr (Fixed) {
                Fixed8 f = at_level_fixed(levels0, ur, vr);
                if (two_levels) {
                    const Fixed8 v1 = at_level_fixed(levels1, ur, vr);
                    Fixed8 w;
                    spread<Wide>(floor_small8(weight * float(kOne)) << (16 - kBits), w);
                    f = {blend16<Wide>(f.lo, v1.lo, w.lo), blend16<Wide>(f.hi, v1.hi, w.hi)};
                }
                unit_of_fixed8<Wide>(f, out);
            } else {
                at_level_float(levels0, ur, vr, out);
                if (two_levels) {
                    std::array<f8, 4> c1;
                    at_level_float(levels1, ur, vr, c1);
                    blend_levels_float(out, c1, weight);
                }
            }
        };
        if constexpr (!Aniso) {
            const LaneLevels levels0 = lane_levels(level0);
            return lookup_reduced(levels0, two_levels ? lane_levels(level1) : levels0, reduce8<Wide>(u, wrap_s), reduce8<Wide>(v, wrap_t), rgba);
        }
        // Anisotropic: the same lookup at each probe (sample()'s loop); a lane adds its k-th
        // only while k < its N.
        const LaneLevels levels0 = lane_levels(level0), levels1 = two_levels ? lane_levels(level1) : levels0;
        auto lookup = [&](const f8& pu, const f8& pv, std::array<f8, 4>& out) {
            lookup_reduced(levels0, levels1, reduce8<Wide>(pu, wrap_s), reduce8<Wide>(pv, wrap_t), out);
        };
        int most_probes = 1;
        for (int lane = 0; lane < simd::kLanes; ++lane) most_probes = std::max(most_probes, int(probes[lane]));
        if (most_probes == 1) return lookup(u, v, rgba);
        rgba = {splat(0.0f), splat(0.0f), splat(0.0f), splat(0.0f)};
        for (int k = 0; k < most_probes; ++k) {
            const f8 t = to_float(splat_i(2 * k + 1)) / to_float(probes + probes) - 0.5f;
            const i8 used = splat_i(k) < probes, moved = probes > 1;  // (one probe: uv itself, as sample() reads it)
            std::array<f8, 4> probe;
            lookup(select(moved, u + t * axis_u, u), select(moved, v + t * axis_v, v), probe);
            for (size_t c = 0; c < 4; ++c) rgba[c] = rgba[c] + select(used, probe[c], splat(0.0f));
        }
        for (size_t c = 0; c < 4; ++c) rgba[c] = rgba[c] / to_float(probes);
    };
    // And a power-of-two texture's repeat wrap mode (pot_), a mask instead of comparisons.
    auto with_filter = [&]<bool Aniso>() {
        if (fixed_point(s)) {
            // (Pot saves 2% on bench_trilinear: not worth another anisotropic copy, nor one
            // for sRGB textures, whose power-of-two lookups mostly take the common one.)
            if constexpr (!Aniso && !Srgb) {
                if (pot_ && s.wrap_s == Wrap::Repeat && s.wrap_t == Wrap::Repeat) return body.template operator()<false, true, true>();
            }
            body.template operator()<Aniso, true, false>();
        } else {
            body.template operator()<Aniso, false, false>();
        }
    };
    if (s.max_anisotropy > 1) with_filter.template operator()<true>();
    else with_filter.template operator()<false>();
}

// The common lookup's conditions: a power-of-two texture repeating on both axes, bilinear
// both ways, no anisotropy; then its numbers.
static bool uniform_lookup(bool pot, const Sampler& s) {
    return pot && s.wrap_s == Wrap::Repeat && s.wrap_t == Wrap::Repeat && s.mag == Filter::Bilinear && s.min == Filter::Bilinear && s.max_anisotropy <= 1;
}

// In the CPU's best copy (simd.h).
void Texture::sample8(const f8& u, const f8& v, const std::array<f8, 4>& d, const Sampler& s, std::array<f8, 4>& rgba) const {
    // The common lookup first, in a copy of its own (texture_uniform.cpp).
    if (uniform_lookup(pot_, s) && lanes::sample_uniform(pot_levels(), u, v, d, s.mip, rgba)) return;
    simd::on_best_path([&]<bool Wide>() {
        if (srgb_) sample_lanes<Wide, true>(u, v, d, s, rgba);
        else sample_lanes<Wide, false>(u, v, d, s, rgba);
    });
}

void Texture::sample_pair(const f8& u0, const f8& v0, const f8& u1, const f8& v1, const std::array<f8, 4>& d0, const std::array<f8, 4>& d1,
                          const Sampler& s, std::array<f8, 4>& rgba0, std::array<f8, 4>& rgba1) const {
    // Together where both groups take the common lookup, in fixed point.
    if (uniform_lookup(pot_, s) && lanes::sample_uniform_pair(pot_levels(), u0, v0, u1, v1, d0, d1, s.mip, rgba0, rgba1)) return;
    sample8(u0, v0, d0, s, rgba0);
    sample8(u1, v1, d1, s, rgba1);
}

// The four groups as two pairs, out of line: inlined, the copies of their derivatives were
// made ahead of the common lookup, on every call.
[[gnu::noinline]] static void sample_four_by_pairs(const Texture& t, const f8* const (&uv)[4], const Sampler& s, std::array<f8, 4> (&rgba)[4]) {
    const auto d = [&](int g) { return std::array<f8, 4>{uv[g][2], uv[g][3], uv[g][4], uv[g][5]}; };
    t.sample_pair(uv[0][0], uv[0][1], uv[1][0], uv[1][1], d(0), d(1), s, rgba[0], rgba[1]);
    t.sample_pair(uv[2][0], uv[2][1], uv[3][0], uv[3][1], d(2), d(3), s, rgba[2], rgba[3]);
}

void Texture::sample_four(const f8* const (&uv)[4], const Sampler& s, std::array<f8, 4> (&rgba)[4]) const {
    if (uniform_lookup(pot_, s) && lanes::sample_uniform_four(pot_levels(), uv, s.mip, rgba)) return;
    sample_four_by_pairs(*this, uv, s, rgba);
}

lanes::PotLevels Texture::pot_levels() const {
    return {texels(), srgb_ ? fixed_texels() : nullptr, &tables_, levels(), float(width()), float(height())};
}

}  // namespace softraster
