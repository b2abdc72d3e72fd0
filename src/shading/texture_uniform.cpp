// The common lookup of Texture::sample8 (texture_lanes.h).
#include "texture_lanes.h"

namespace softraster::lanes {
namespace {

// ---- the common lookup
//
// A power-of-two texture repeating on both axes, bilinear both ways, no anisotropy, every lane
// on the same level(s): what real models and the corridor mostly ask for. Linear textures
// filter in fixed point (sample_uniform_linear), sRGB ones in float (sample_uniform_srgb).
// The body of sample_lanes with everything those conditions fix taken out (no level tables,
// no wrap or filter choices per lane, a level's numbers as scalars), and a small function of
// its own (the general body's stack frame and dispatch would cost it a sixth of its time):
// the same operations, the same bits (Texture.UniformLookupsOnPowerOfTwoTexturesEqualOneAtATime).

// Level k's sample point, from level 0's (fu, fv): the index of its footprint's first texel
// and the weights (0..255) across and up.
struct LevelPoint {
    i8 index, fx, fy;
};
template <bool Wide>
inline void level_point(const PotLevels& t, const i8& fu, const i8& fv, int k, LevelPoint& out) {
    const LevelTables& n = *t.tables;
    const i8 x = (fu >> n.shift_u[k]) - 128, y = (fv >> n.shift_v[k]) - 128;
    const i8 i0 = (x >> 8) & n.mask_w[k], j0 = (y >> 8) & n.mask_h[k];
    out = {tile_index8(n.offset[k], n.tiles_x[k], i0, j0), x & 255, y & 255};
}
#if SOFTRASTER_HAS_AVX2_PATH
// The level's numbers come as broadcasts from memory (LevelTables), and the shifts by them
// as per-lane shifts of a broadcast count: neither takes the shuffle port, which the texel
// loads keep busy.
template <>
[[gnu::target("avx2")]] inline void level_point<true>(const PotLevels& t, const i8& fu, const i8& fv, int k, LevelPoint& out) {
    const LevelTables& n = *t.tables;
    const __m256i x = _mm256_sub_epi32(_mm256_srav_epi32(__m256i(fu), _mm256_set1_epi32(n.shift_u[k])), _mm256_set1_epi32(128));
    const __m256i y = _mm256_sub_epi32(_mm256_srav_epi32(__m256i(fv), _mm256_set1_epi32(n.shift_v[k])), _mm256_set1_epi32(128));
    const __m256i i0 = _mm256_and_si256(_mm256_srai_epi32(x, 8), _mm256_set1_epi32(n.mask_w[k]));
    const __m256i j0 = _mm256_and_si256(_mm256_srai_epi32(y, 8), _mm256_set1_epi32(n.mask_h[k]));
    // tile_index8, as (((j0 / 4) tiles_x + i0 / 4) 5 + j0 % 4) 5 + i0 % 4 + offset, with shifts
    // and adds for the products (tiles_x is a power of two here): a multiply's 10-cycle latency
    // three times over would lengthen the chain the texel loads wait on.
    static_assert(Texture::kTileSide == 5);
    const __m256i tile = _mm256_add_epi32(_mm256_sllv_epi32(_mm256_srai_epi32(j0, 2), _mm256_set1_epi32(n.log2_tiles_x[k])), _mm256_srai_epi32(i0, 2));
    const __m256i three = _mm256_set1_epi32(3);
    const __m256i tile5 = _mm256_add_epi32(_mm256_slli_epi32(tile, 2), tile);
    const __m256i row = _mm256_add_epi32(tile5, _mm256_and_si256(j0, three));
    const __m256i row5 = _mm256_add_epi32(_mm256_slli_epi32(row, 2), row);
    const __m256i index = _mm256_add_epi32(_mm256_add_epi32(row5, _mm256_and_si256(i0, three)), _mm256_set1_epi32(n.offset[k]));
    const __m256i low = _mm256_set1_epi32(255);
    out = {i8(index), i8(_mm256_and_si256(x, low)), i8(_mm256_and_si256(y, low))};
}
#endif
// The level(s) the lanes read, when all read the same: select_lod's, on eight lanes.
struct UniformLevels {
    int level;
    bool two;  // a second level, level + 1, with these weights
    f8 weight;
};
template <bool Wide>
inline bool uniform_levels(const PotLevels& t, const f8* d, MipFilter mip, UniformLevels& out) {
    using simd::splat, simd::splat_i;
    LaneLod lod{splat_i(0), splat_i(0), splat(0.0f)};
    if (mip != MipFilter::None) {
        f8 rx, ry;
        footprint_axes8(d, t.w, t.h, rx, ry);
        const f8 rho2 = simd::select(rx > ry, rx, ry);
        lod = lane_lod<Wide>(rho2, rho2 > 1.0f, mip, t.levels - 1);
    }
    out.level = lod.level0[0];
    if (simd::any(lod.level0 != out.level)) return false;
    out.two = simd::any(lod.weight != 0.0f);
    out.weight = lod.weight;
    return out.level + (out.two ? 1 : 0) < 16;  // (past the tables otherwise)
}

// The levels are read before they are known, as a guess: the ones this thread's last lookup
// read, which the next group of a row nearly always reads too. The level of detail (some 30
// cycles of float arithmetic, then the level's numbers from the tables) would otherwise head
// the lookup's longest chain, before the texel addresses and their loads; with the guess
// the loads start at once, and the level of detail, worked out beside them, only confirms
// it (a well-predicted branch). A wrong guess reads the right levels again. Either way the
// values are the same; only the time differs. (The sRGB lookup does without: its gathers,
// not this chain, bound its time, and the guess made it no faster.)
struct LevelGuess {
    int level = 0;
    bool two = false;
};
thread_local LevelGuess t_last_levels;  // (below 16 levels: a texture's tables repeat its last level up to there)
// Whether the levels read were the right ones; if not, the next guess is l's.
inline bool guessed_right(LevelGuess g, const UniformLevels& l) {
    if (g.level == l.level && g.two == l.two) return true;
    t_last_levels = {l.level, l.two};
    return false;
}

// Level 0's sample point in 1/256 texel steps (sample_level_fixed): exact, u being in [0, 1]
// and the side a power of two, so that truncation is the floor; level k's is it shifted right
// by k, up to a side of 1.
template <bool Wide>
inline i8 fixed_point(const f8& u, float side) {
    return simd::to_int(reduce8<Wide>(u, Wrap::Repeat) * (256.0f * side));
}

// Linear textures: the fixed-point filter (sample_level_fixed), for G groups of eight lanes
// in D sets, each set's groups with the same derivatives d[set]: one group, a row of quads'
// first and second rows (Texture::sample_quad_rows: one level of detail serves both), or two
// such pairs side by side (Texture::sample_quad_block), whose levels must then agree too. The
// work goes phase by phase, all groups' texel addresses, then all their loads, then all the
// filtering, so that a second group's loads do not queue behind the first's filter (a lookup
// is a long chain of dependent steps; side by side, they overlap), and one call's fixed costs
// (the level of detail, the level's numbers, the call itself) serve all G groups.
template <bool Wide, int G, int D>
inline bool sample_uniform_linear(const PotLevels& t, const f8* const (&u)[G], const f8* const (&v)[G], const f8* const (&d)[D], MipFilter mip,
                                  std::array<f8, 4>* const (&rgba)[G]) {
    static_assert(G % D == 0);
    using simd::to_int;
    i8 fu[G], fv[G];
    for (int g = 0; g < G; ++g) fu[g] = fixed_point<Wide>(*u[g], t.w), fv[g] = fixed_point<Wide>(*v[g], t.h);
    LevelPoint p[G][2];  // [group][first or second level]
    i8 texel[G][2][4];
    UniformLevels l[D], all;
    for (;;) {  // (twice only after a wrong guess, which guessed_right corrects)
        const LevelGuess guess = t_last_levels;
        const int levels = guess.two ? 2 : 1;
        for (int g = 0; g < G; ++g)
            for (int k = 0; k < levels; ++k) level_point<Wide>(t, fu[g], fv[g], guess.level + k, p[g][k]);
        for (int g = 0; g < G; ++g)
            for (int k = 0; k < levels; ++k) load_footprints<Wide>(t.texels, p[g][k].index, texel[g][k]);
        for (int k = 0; k < D; ++k)
            if (!uniform_levels<Wide>(t, d[k], mip, l[k]) || l[k].level != l[0].level) return false;
        all = l[0];
        for (int k = 1; k < D; ++k) all.two = all.two || l[k].two;  // (a set without a second level blends it by 0: exact)
        if (all.level + (all.two ? 1 : 0) >= 16) return false;
        if (guessed_right(guess, all)) [[likely]] break;
    }
    Fixed8 w[D];
    if (all.two)
        for (int k = 0; k < D; ++k) spread<Wide>(to_int(l[k].weight * 256.0f) << 8, w[k]);  // (weight in [0, 1): truncation is the floor)
    for (int g = 0; g < G; ++g) {
        Fixed8 f = bilinear16<Wide>(texel[g][0], p[g][0].fx, p[g][0].fy);
        if (all.two) {
            const Fixed8 f1 = bilinear16<Wide>(texel[g][1], p[g][1].fx, p[g][1].fy);
            const Fixed8& wg = w[g / (G / D)];
            f = {blend16<Wide>(f.lo, f1.lo, wg.lo), blend16<Wide>(f.hi, f1.hi, wg.hi)};
        }
        unit_of_fixed8<Wide>(f, *rgba[g]);
    }
    return true;
}

// sRGB textures: each texel decoded through the table (a gather per channel), then the
// float filter (sample_level), as the general body computes them.
template <bool Wide>
inline void srgb_level(const PotLevels& t, const uint32_t* decode, const f8& ur, const f8& vr, int level, std::array<f8, 4>& out) {
    using simd::to_float;
    const LevelTables& n = *t.tables;
    const f8 x = ur * float(n.width[level]) - 0.5f, y = vr * float(n.height[level]) - 0.5f;
    const i8 i0 = floor_small8(x), j0 = floor_small8(y);
    const f8 fx = x - to_float(i0), fy = y - to_float(j0);
    i8 texel[4];
    load_footprints<Wide>(t.texels, tile_index8(n.offset[level], n.tiles_x[level], i0 & n.mask_w[level], j0 & n.mask_h[level]), texel);
    std::array<f8, 4> c[4];
    for (size_t p = 0; p < 4; ++p) texel_channels<Wide, true>(texel[p], decode, c[p]);
    bilinear_float(c, fx, fy, out);
}
template <bool Wide>
inline bool sample_uniform_srgb(const PotLevels& t, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba) {
    UniformLevels l;
    if (!uniform_levels<Wide>(t, d.data(), mip, l)) return false;
    const f8 ur = reduce8<Wide>(u, Wrap::Repeat), vr = reduce8<Wide>(v, Wrap::Repeat);
    const uint32_t* decode = reinterpret_cast<const uint32_t*>(srgb::tables().decode.data());
    srgb_level<Wide>(t, decode, ur, vr, l.level, rgba);
    if (l.two) {
        std::array<f8, 4> c1;
        srgb_level<Wide>(t, decode, ur, vr, l.level + 1, c1);
        blend_levels_float(rgba, c1, l.weight);
    }
    return true;
}

}  // namespace

// Whether two groups' derivatives are the same (the same quads'); where not, each group
// takes its own level of detail.
template <bool Wide>
inline bool same_quads(const f8* d0, const f8* d1) {
    return !simd::any((d0[0] != d1[0]) | (d0[1] != d1[1]) | (d0[2] != d1[2]) | (d0[3] != d1[3]));
}

bool sample_uniform_rows(const PotLevels& t, const f8& u0, const f8& v0, const f8& u1, const f8& v1, const std::array<f8, 4>& d0,
                         const std::array<f8, 4>& d1, MipFilter mip, std::array<f8, 4>& rgba0, std::array<f8, 4>& rgba1) {
    // (All of it in the lambda, the CPU path's own copy: vectors compared or copied outside it
    // would be compiled without AVX, lane by lane.)
    return simd::on_best_path<simd::kGenericApart>([&]<bool Wide>() {
        if (!same_quads<Wide>(d0.data(), d1.data())) return false;
        const f8* const u[2] = {&u0, &u1};
        const f8* const v[2] = {&v0, &v1};
        const f8* const d[1] = {d0.data()};
        std::array<f8, 4>* const rgba[2] = {&rgba0, &rgba1};
        return sample_uniform_linear<Wide, 2, 1>(t, u, v, d, mip, rgba);
    });
}

bool sample_uniform_block(const PotLevels& t, const f8* const (&uv)[4], MipFilter mip, std::array<f8, 4> (&rgba)[4]) {
    return simd::on_best_path<simd::kGenericApart>([&]<bool Wide>() {
        const f8* const d[4] = {uv[0] + 2, uv[1] + 2, uv[2] + 2, uv[3] + 2};
        if (!same_quads<Wide>(d[0], d[1]) || !same_quads<Wide>(d[2], d[3])) return false;
        const f8* const u[4] = {uv[0], uv[1], uv[2], uv[3]};
        const f8* const v[4] = {uv[0] + 1, uv[1] + 1, uv[2] + 1, uv[3] + 1};
        const f8* const pairs[2] = {d[0], d[2]};
        std::array<f8, 4>* const out[4] = {&rgba[0], &rgba[1], &rgba[2], &rgba[3]};
        return sample_uniform_linear<Wide, 4, 2>(t, u, v, pairs, mip, out);
    });
}

bool sample_uniform(const PotLevels& t, bool srgb, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba) {
    if (srgb) return simd::on_best_path<simd::kGenericApart>([&]<bool Wide>() { return sample_uniform_srgb<Wide>(t, u, v, d, mip, rgba); });
    return simd::on_best_path<simd::kGenericApart>([&]<bool Wide>() {
        const f8* const uu[1] = {&u};
        const f8* const vv[1] = {&v};
        const f8* const dd[1] = {d.data()};
        std::array<f8, 4>* const out[1] = {&rgba};
        return sample_uniform_linear<Wide, 1, 1>(t, uu, vv, dd, mip, out);
    });
}

}  // namespace softraster::lanes
