// The common lookup of Texture::sample8 (texture_lanes.h).
#include "texture_lanes.h"
#include "texture_lanes512.h"

namespace softraster::lanes {
namespace {

// The lookup's copies: the generic and AVX2 ones every phase has (simd::on_best_path), and
// one for AVX-512 of its own (texture_lanes512.h), where its loads and 16-bit filter take
// about half the instructions.
enum class Path { Generic, Avx2, Avx512 };

// ---- the common lookup
//
// A power-of-two texture repeating on both axes, bilinear both ways, no anisotropy, every lane
// on the same level(s) or, where the level of detail steps, on one of two neighbouring ones:
// what real models and the corridor mostly ask for, filtered in fixed point
// (sample_uniform_fixed), linear and sRGB textures alike.
// The body of sample_lanes with everything those conditions fix taken out (no level tables,
// no wrap or filter choices per lane, a level's numbers as scalars), and a small function of
// its own (the general body's stack frame and dispatch would cost it a sixth of its time):
// the same operations, the same bits (Texture.UniformLookupsOnPowerOfTwoTexturesEqualOneAtATime).

// Level k's sample point, from level 0's (fu, fv) in 1/2^Bits texel steps: the index of its
// footprint's first texel and the weights (0..2^Bits - 1) across and up.
struct LevelPoint {
    i8 index, fx, fy;
};
// The level's numbers are number(table): one level's for all lanes (level_point_on), or each
// lane's own (level_point_lanes).
template <int Bits, class Number>
inline void level_point_of(const PotLevels& t, const i8& fu, const i8& fv, const Number& number, LevelPoint& out) {
    const LevelTables& n = *t.tables;
    constexpr int kOne = 1 << Bits;
    const i8 x = (fu >> number(n.shift_u)) - kOne / 2, y = (fv >> number(n.shift_v)) - kOne / 2;
    const i8 i0 = (x >> Bits) & number(n.mask_w), j0 = (y >> Bits) & number(n.mask_h);
    out = {tile_index8(number(n.offset), number(n.tiles_x), i0, j0), x & (kOne - 1), y & (kOne - 1)};
}
#if SOFTRASTER_HAS_AVX2_PATH
// The level's numbers come as broadcasts from memory (LevelTables), and the shifts by them
// as per-lane shifts of a broadcast count: neither takes the shuffle port, which the texel
// loads keep busy.
template <int Bits>
[[gnu::target("avx2")]] inline void level_point_avx2(const PotLevels& t, const i8& fu, const i8& fv, int k, LevelPoint& out) {
    const LevelTables& n = *t.tables;
    constexpr int kOne = 1 << Bits;
    const __m256i x = _mm256_sub_epi32(_mm256_srav_epi32(__m256i(fu), _mm256_set1_epi32(n.shift_u[k])), _mm256_set1_epi32(kOne / 2));
    const __m256i y = _mm256_sub_epi32(_mm256_srav_epi32(__m256i(fv), _mm256_set1_epi32(n.shift_v[k])), _mm256_set1_epi32(kOne / 2));
    const __m256i i0 = _mm256_and_si256(_mm256_srai_epi32(x, Bits), _mm256_set1_epi32(n.mask_w[k]));
    const __m256i j0 = _mm256_and_si256(_mm256_srai_epi32(y, Bits), _mm256_set1_epi32(n.mask_h[k]));
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
    const __m256i low = _mm256_set1_epi32(kOne - 1);
    out = {i8(index), i8(_mm256_and_si256(x, low)), i8(_mm256_and_si256(y, low))};
}
#endif
#if SOFTRASTER_HAS_AVX2_PATH
// The same for two groups at once, in 512-bit registers (the AVX-512 copy): the same
// operations on sixteen lanes, then each group's half.
template <int Bits>
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline void level_points_avx512(const PotLevels& t, const i8& fu0, const i8& fu1, const i8& fv0,
                                                                               const i8& fv1, int k, LevelPoint& out0, LevelPoint& out1) {
    using v16 = avx512::i32x16;
    const LevelTables& n = *t.tables;
    constexpr int kOne = 1 << Bits;
    const v16 fu = v16(avx512::join(__m256i(fu0), __m256i(fu1))), fv = v16(avx512::join(__m256i(fv0), __m256i(fv1)));
    const v16 x = (fu >> avx512::splat(n.shift_u[k])) - kOne / 2, y = (fv >> avx512::splat(n.shift_v[k])) - kOne / 2;
    const v16 i0 = (x >> Bits) & avx512::splat(n.mask_w[k]), j0 = (y >> Bits) & avx512::splat(n.mask_h[k]);
    // tile_index8 as level_point_avx2 works it out: (((j0 / 4) tiles_x + i0 / 4) 5 + j0 % 4) 5 + i0 % 4 + offset.
    const v16 tile = ((j0 >> 2) << avx512::splat(n.log2_tiles_x[k])) + (i0 >> 2);
    const v16 row = (tile << 2) + tile + (j0 & 3);
    const v16 index = (row << 2) + row + (i0 & 3) + avx512::splat(n.offset[k]);
    const v16 fx = x & (kOne - 1), fy = y & (kOne - 1);
    out0 = {i8(avx512::low_half(__m512i(index))), i8(avx512::low_half(__m512i(fx))), i8(avx512::low_half(__m512i(fy)))};
    out1 = {i8(avx512::high_half(__m512i(index))), i8(avx512::high_half(__m512i(fx))), i8(avx512::high_half(__m512i(fy)))};
}
#endif
#if SOFTRASTER_HAS_AVX2_PATH
// The corridor's texel loads wait on memory most where a row of quads reaches texels no row
// above it read: a screen row walks along its row of texel tiles, which the hardware's
// prefetch of neighbouring lines follows, but each row below starts on tiles further along v.
// So a call on two pairs of rows (sample_uniform_four) asks for the footprints kRowsAhead rows
// below its second rows, at its first level: the rows a later call of the same tile reads,
// after the rest of this row of quads. Their sample points are the second rows' shifted by kRowsAhead
// times the derivatives across rows, in the same fixed point (the level's mask wraps them as
// the lookup's own); a prefetch only asks, so an approximate point costs no more than a wasted
// line. Measured in docs/performance.md ("Texels of the rows below, fetched ahead").
inline constexpr float kRowsAhead = 3.0f;
// A fixed-point coordinate f moved by scale times its derivative across rows. (Intrinsics:
// their conversion and sum are defined for any derivative, the vector operators' are not for
// one out of range. The vectors by reference, as the other AVX2 helpers here take them: see
// simd_avx512.h on passing them by value across copies.)
[[gnu::target("avx2")]] inline void rows_below(const i8& f, const f8& across_rows, float scale, i8& out) {
    out = i8(_mm256_add_epi32(__m256i(f), _mm256_cvttps_epi32(__m256(across_rows * scale))));
}
template <Path P, int Bits, bool Srgb>
inline void fetch_rows_below(const PotLevels& t, const i8& fu0, const i8& fv0, const f8* d0, const i8& fu1, const i8& fv1, const f8* d1, int level) {
    constexpr float kScale = kRowsAhead * float(1 << Bits);
    i8 u0, v0, u1, v1;
    rows_below(fu0, d0[2], kScale * t.w, u0), rows_below(fv0, d0[3], kScale * t.h, v0);
    rows_below(fu1, d1[2], kScale * t.w, u1), rows_below(fv1, d1[3], kScale * t.h, v1);
    LevelPoint p[2];
    if constexpr (P == Path::Avx512) level_points_avx512<Bits>(t, u0, u1, v0, v1, level, p[0], p[1]);
    else level_point_avx2<Bits>(t, u0, v0, level, p[0]), level_point_avx2<Bits>(t, u1, v1, level, p[1]);
    // (An sRGB texture's footprint, 8 bytes a texel, ends 56 bytes on, mostly in the next
    // line: its last texel is asked for too. A linear one's 28 bytes mostly share one.)
    for (const LevelPoint& group : p)
        for (int lane = 0; lane < simd::kLanes; ++lane) {
            if constexpr (Srgb) {
                __builtin_prefetch(t.fixed_texels + group.index[lane]);
                __builtin_prefetch(t.fixed_texels + group.index[lane] + Texture::kTileSide + 1);
            } else {
                __builtin_prefetch(t.texels + group.index[lane]);
            }
        }
}
#endif
// The CPU path's copy.
template <bool Wide, int Bits>
inline void level_point_on(const PotLevels& t, const i8& fu, const i8& fv, int k, LevelPoint& out) {
#if SOFTRASTER_HAS_AVX2_PATH
    if constexpr (Wide) return level_point_avx2<Bits>(t, fu, fv, k, out);
#endif
    level_point_of<Bits>(t, fu, fv, [k](const std::array<int32_t, 16>& a) { return a[size_t(k)]; }, out);
}
// The same on lanes at two neighbouring levels, k where `up` is clear and k + 1 where set.
// (For the few groups that straddle the line where the level of detail steps.)
template <int Bits>
inline void level_point_lanes(const PotLevels& t, const i8& fu, const i8& fv, int k, const i8& up, LevelPoint& out) {
    level_point_of<Bits>(
        t, fu, fv, [&](const std::array<int32_t, 16>& a) { return simd::select(up, simd::splat_i(a[size_t(k) + 1]), simd::splat_i(a[size_t(k)])); }, out);
}
// Each lane's level(s) of detail (select_lod), from its quad's derivatives d.
template <bool Wide>
inline LaneLod lods_of_derivatives(const PotLevels& t, const f8* d, MipFilter mip) {
    using simd::splat, simd::splat_i;
    if (mip == MipFilter::None) return {splat_i(0), splat_i(0), splat(0.0f)};
    f8 rx, ry;
    footprint_axes8(d, t.w, t.h, rx, ry);
    const f8 rho2 = simd::select(rx > ry, rx, ry);
    return lane_lod<Wide>(rho2, rho2 > 1.0f, mip, t.levels - 1);
}
// Whether all lanes read one level (and perhaps the next); if so, which.
inline bool one_level(const LaneLod& lod, int& level) {
    level = lod.level0[0];
    return !simd::any(lod.level0 != level);
}

// The levels are read before they are known, as a guess: the ones this thread's last lookup
// read, which the next group of a row nearly always reads too. The level of detail (some 30
// cycles of float arithmetic, then the level's numbers from the tables) would otherwise head
// the lookup's longest chain, before the texel addresses and their loads; with the guess
// the loads start at once, and the level of detail, worked out beside them, only confirms
// it (a well-predicted branch). A wrong guess reads the right levels again. Either way the
// values are the same; only the time differs.
struct LevelGuess {
    int level = 0;
    bool two = false;
};
thread_local LevelGuess t_last_levels;  // (below 16 levels: a texture's tables repeat its last level up to there)
// Whether the levels read were the right ones; if not, the next guess is l's.
inline bool guessed_right(LevelGuess g, LevelGuess l) {
    if (g.level == l.level && g.two == l.two) return true;
    t_last_levels = {l.level, l.two};
    return false;
}

// Level 0's sample point in 1/2^Bits texel steps (sample_level_fixed): exact, u being in
// [0, 1] and the side a power of two, so that truncation is the floor; level k's is it
// shifted right by k, up to a side of 1.
template <bool Wide, int Bits>
inline i8 fixed_point(const f8& u, float side) {
    return simd::to_int(reduce8<Wide>(u, Wrap::Repeat) * (float(1 << Bits) * side));
}

// A corner of a group's footprints, as the lookup keeps it between its phases: a linear
// texture's eight 8-bit texels, or an sRGB texture's eight decoded ones (Fixed8's two
// registers; on the AVX-512 copy, one).
template <Path P, bool Srgb>
struct CornerOf {
    using type = std::conditional_t<Srgb, Fixed8, i8>;
};
#if SOFTRASTER_HAS_AVX2_PATH
template <>
struct CornerOf<Path::Avx512, true> {
    using type = __m512i;
};
#endif
// A group's footprints at one level.
template <Path P, bool Srgb>
inline void load_corners(const PotLevels& t, const i8& index, typename CornerOf<P, Srgb>::type (&corner)[4]) {
#if SOFTRASTER_HAS_AVX2_PATH
    if constexpr (P == Path::Avx512) {
        if constexpr (Srgb) avx512::load_footprints_fixed(t.fixed_texels, index, corner);
        else avx512::load_footprints(t.texels, index, corner);
    } else
#endif
    if constexpr (Srgb) load_footprints_fixed<P != Path::Generic>(t.fixed_texels, index, corner);
    else load_footprints<P != Path::Generic>(t.texels, index, corner);
}

#if SOFTRASTER_HAS_AVX2_PATH
// sample_uniform_fixed's last phase on the AVX-512 copy: each group's levels filtered, blended
// and made floats, a register per group and level. (A function of its own with the copy's
// instructions: the 512-bit values cross no call without them, which Clang refuses.)
template <int G, int D, bool Srgb, int Bits>
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] inline void filter_avx512(const typename CornerOf<Path::Avx512, Srgb>::type (&texel)[G][2][4],
                                                                         const LevelPoint (&p)[G][2], const i8 (&weight)[D], bool two,
                                                                         std::array<f8, 4>* const (&rgba)[G]) {
    __m512i w[D];
    if (two)
        for (int k = 0; k < D; ++k) w[k] = avx512::spread(weight[k]);
    for (int g = 0; g < G; ++g) {
        __m512i f[2];
        for (int k = 0; k < (two ? 2 : 1); ++k) {
            if constexpr (Srgb) f[k] = avx512::bilinear_fixed<Bits>(texel[g][k], p[g][k].fx, p[g][k].fy);
            else f[k] = avx512::bilinear16(texel[g][k], p[g][k].fx, p[g][k].fy);
        }
        avx512::unit_of_fixed(two ? avx512::blend(f[0], f[1], w[g / (G / D)]) : f[0], *rgba[g]);
    }
}
#endif

// The fixed-point filter (sample_level_fixed), for G groups of eight lanes in D sets, each
// set's groups with the same derivatives d[set]: one group, a row of quads' first and second
// rows (Texture::sample_pair: one level of detail serves both), two such pairs side by side
// (Texture::sample_four), or any two or four groups, each a set of its own. All lanes'
// first levels must be within one of each other. The work goes
// phase by phase, all groups' texel addresses, then all their loads, then all the filtering,
// so that a second group's loads do not queue behind the first's filter (a lookup is a long
// chain of dependent steps; side by side, they overlap), and one call's fixed costs (the
// level of detail, the level's numbers, the call itself) serve all G groups. Srgb: the
// texels come already decoded onto the fixed-point scale (Texture::fixed_texels), eight
// bytes each, from the same places.
template <Path P, int G, int D, bool Srgb>
inline bool sample_uniform_fixed(const PotLevels& t, const f8* const (&u)[G], const f8* const (&v)[G], const f8* const (&d)[D], MipFilter mip,
                                 std::array<f8, 4>* const (&rgba)[G]) {
    static_assert(G % D == 0);
    constexpr bool Wide = P != Path::Generic;
    using simd::to_int;
    constexpr int kBits = Texture::fraction_bits(Srgb);
    i8 fu[G], fv[G];
    for (int g = 0; g < G; ++g) fu[g] = fixed_point<Wide, kBits>(*u[g], t.w), fv[g] = fixed_point<Wide, kBits>(*v[g], t.h);
    LevelPoint p[G][2];  // [group][first or second level]
    using Texels = typename CornerOf<P, Srgb>::type;
    Texels texel[G][2][4];
    auto load = [&](int levels) {
        for (int g = 0; g < G; ++g)
            for (int k = 0; k < levels; ++k) load_corners<P, Srgb>(t, p[g][k].index, texel[g][k]);
    };
    LaneLod lod[D];
    bool two = false;  // a second level to blend in
    for (;;) {  // (twice only after a wrong guess, which guessed_right corrects)
        const LevelGuess guess = t_last_levels;
#if SOFTRASTER_HAS_AVX2_PATH
        if constexpr (P == Path::Avx512 && G % 2 == 0) {
            for (int g = 0; g < G; g += 2)
                for (int k = 0; k < (guess.two ? 2 : 1); ++k)
                    level_points_avx512<kBits>(t, fu[g], fu[g + 1], fv[g], fv[g + 1], guess.level + k, p[g][k], p[g + 1][k]);
        } else
#endif
            for (int g = 0; g < G; ++g)
                for (int k = 0; k < (guess.two ? 2 : 1); ++k) level_point_on<Wide, kBits>(t, fu[g], fv[g], guess.level + k, p[g][k]);
        load(guess.two ? 2 : 1);
#if SOFTRASTER_HAS_AVX2_PATH
        if constexpr (P != Path::Generic && G == 4 && D == 2) fetch_rows_below<P, kBits, Srgb>(t, fu[1], fv[1], d[0], fu[3], fv[3], d[1], guess.level);
#endif
        int level[D];
        bool uniform = true;
        for (int k = 0; k < D; ++k) {
            lod[k] = lods_of_derivatives<Wide>(t, d[k], mip);
            uniform = uniform && one_level(lod[k], level[k]) && level[k] == level[0];
        }
        two = false;
        for (int k = 0; k < D; ++k) two = two || simd::any(lod[k].weight != 0.0f);  // (a set without a second level blends it by 0: exact)
        if (!uniform) {
            // Lanes on two neighbouring levels (where the level of detail steps from one to
            // the next): each lane's own numbers, no guess; on more, the general lookup.
            int low = 16, high = -1;
            for (int k = 0; k < D; ++k)
                for (int lane = 0; lane < simd::kLanes; ++lane) low = std::min(low, lod[k].level0[lane]), high = std::max(high, lod[k].level0[lane]);
            if (high != low + 1 || high + (two ? 1 : 0) >= 16) return false;
            for (int g = 0; g < G; ++g) {
                const i8 up = lod[g / (G / D)].level0 != low;
                for (int k = 0; k < (two ? 2 : 1); ++k) level_point_lanes<kBits>(t, fu[g], fv[g], low + k, up, p[g][k]);
            }
            load(two ? 2 : 1);
            break;
        }
        if (level[0] + (two ? 1 : 0) >= 16) return false;  // (past the tables)
        if (guessed_right(guess, {level[0], two})) [[likely]] break;
    }
    // The filter, on this copy's registers, with each set's weight of the second level as a
    // 16-bit fraction (weight in [0, 1): truncation is the floor).
    i8 weight[D];
    if (two)
        for (int k = 0; k < D; ++k) weight[k] = to_int(lod[k].weight * float(1 << kBits)) << (16 - kBits);
#if SOFTRASTER_HAS_AVX2_PATH
    if constexpr (P == Path::Avx512) filter_avx512<G, D, Srgb, kBits>(texel, p, weight, two, rgba);
    else
#endif
    {
        auto bilinear = [&](const Texels (&c)[4], const LevelPoint& at) {
            if constexpr (Srgb) return bilinear_fixed<Wide, kBits>(c, at.fx, at.fy);
            else return bilinear16<Wide>(c, at.fx, at.fy);
        };
        Fixed8 w[D];
        if (two)
            for (int k = 0; k < D; ++k) spread<Wide>(weight[k], w[k]);
        for (int g = 0; g < G; ++g) {
            Fixed8 f = bilinear(texel[g][0], p[g][0]);
            if (two) {
                const Fixed8 f1 = bilinear(texel[g][1], p[g][1]);
                const Fixed8& wg = w[g / (G / D)];
                f = {blend16<Wide>(f.lo, f1.lo, wg.lo), blend16<Wide>(f.hi, f1.hi, wg.hi)};
            }
            unit_of_fixed8<Wide>(f, *rgba[g]);
        }
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

#if SOFTRASTER_HAS_AVX2_PATH
// The AVX-512 copy, flattened as simd::run_avx2 flattens the AVX2 one.
template <bool Srgb, class F>
[[gnu::target(SOFTRASTER_AVX512_TARGET_NAMES)]] SOFTRASTER_FLATTEN bool run_avx512(const F& f) {
    return f.template operator()<Path::Avx512, Srgb>();
}
#endif
// Each entry point: a copy per kind of texel and CPU path, chosen before the call (one
// function holding both kinds' lookups spilled more of its registers).
template <class F>
inline bool per_kind_and_path(const PotLevels& t, const F& f) {
    auto kind = [&]<bool Srgb>() {
#if SOFTRASTER_HAS_AVX2_PATH
        if (simd::cpu_has_avx512()) return run_avx512<Srgb>(f);
#endif
        return simd::on_best_path<simd::kGenericApart>([&]<bool Wide>() { return f.template operator()<Wide ? Path::Avx2 : Path::Generic, Srgb>(); });
    };
    return t.fixed_texels ? kind.template operator()<true>() : kind.template operator()<false>();
}

bool sample_uniform_pair(const PotLevels& t, const f8& u0, const f8& v0, const f8& u1, const f8& v1, const std::array<f8, 4>& d0,
                         const std::array<f8, 4>& d1, MipFilter mip, std::array<f8, 4>& rgba0, std::array<f8, 4>& rgba1) {
    // (All of it in the lambda, the CPU path's own copy: vectors compared or copied outside it
    // would be compiled without AVX, lane by lane.)
    return per_kind_and_path(t, [&]<Path P, bool Srgb>() {
        const f8* const u[2] = {&u0, &u1};
        const f8* const v[2] = {&v0, &v1};
        std::array<f8, 4>* const rgba[2] = {&rgba0, &rgba1};
        if (!same_quads<P != Path::Generic>(d0.data(), d1.data())) {  // (two groups of different quads: a level of detail each)
            const f8* const d[2] = {d0.data(), d1.data()};
            return sample_uniform_fixed<P, 2, 2, Srgb>(t, u, v, d, mip, rgba);
        }
        const f8* const d[1] = {d0.data()};
        return sample_uniform_fixed<P, 2, 1, Srgb>(t, u, v, d, mip, rgba);
    });
}

bool sample_uniform_four(const PotLevels& t, const f8* const (&uv)[4], MipFilter mip, std::array<f8, 4> (&rgba)[4]) {
    // Two pairs of quad rows first; then (any four groups, or a block whose levels span more
    // than two) each group with its own derivatives, in a copy of its own. Each copy picks
    // out the numbers itself: with the two copies in one function, or the numbers picked out
    // by a helper both share, the first copy's code changed and bench_trilinear took 3 to 6%
    // longer (docs/performance.md).
    const bool pairs = per_kind_and_path(t, [&]<Path P, bool Srgb>() {
        const f8* const d[4] = {uv[0] + 2, uv[1] + 2, uv[2] + 2, uv[3] + 2};
        if (!same_quads<P != Path::Generic>(d[0], d[1]) || !same_quads<P != Path::Generic>(d[2], d[3])) return false;
        const f8* const u[4] = {uv[0], uv[1], uv[2], uv[3]};
        const f8* const v[4] = {uv[0] + 1, uv[1] + 1, uv[2] + 1, uv[3] + 1};
        const f8* const sets[2] = {d[0], d[2]};
        std::array<f8, 4>* const out[4] = {&rgba[0], &rgba[1], &rgba[2], &rgba[3]};
        return sample_uniform_fixed<P, 4, 2, Srgb>(t, u, v, sets, mip, out);
    });
    return pairs || per_kind_and_path(t, [&]<Path P, bool Srgb>() {
        const f8* const u[4] = {uv[0], uv[1], uv[2], uv[3]};
        const f8* const v[4] = {uv[0] + 1, uv[1] + 1, uv[2] + 1, uv[3] + 1};
        const f8* const d[4] = {uv[0] + 2, uv[1] + 2, uv[2] + 2, uv[3] + 2};
        std::array<f8, 4>* const out[4] = {&rgba[0], &rgba[1], &rgba[2], &rgba[3]};
        return sample_uniform_fixed<P, 4, 4, Srgb>(t, u, v, d, mip, out);
    });
}

bool sample_uniform(const PotLevels& t, const f8& u, const f8& v, const std::array<f8, 4>& d, MipFilter mip, std::array<f8, 4>& rgba) {
    return per_kind_and_path(t, [&]<Path P, bool Srgb>() {
        const f8* const uu[1] = {&u};
        const f8* const vv[1] = {&v};
        const f8* const dd[1] = {d.data()};
        std::array<f8, 4>* const out[1] = {&rgba};
        return sample_uniform_fixed<P, 1, 1, Srgb>(t, uu, vv, dd, mip, out);
    });
}

}  // namespace softraster::lanes
