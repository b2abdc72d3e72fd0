// The environment term for eight fragments (environment_lighting.h's environment_light8):
// equirect_uv, environment_irradiance, environment_specular and environment_brdf lane by
// lane, the same operations in the same order, with the texels read by gathers, so that
// each lane's bits are the one-fragment formula's.
#include "softraster/shading/environment_lighting.h"

#include <algorithm>
#include <cmath>

#include <sleef.h>

#include "texture_lanes.h"

namespace softraster {
namespace {

using simd::f8, simd::i8, simd::vec3x8, simd::splat, simd::splat_i, simd::select;

// std::clamp(x, lo, hi) lane by lane: lo where x < lo, hi where hi < x, else x (a NaN stays).
f8 clamp_as_std(f8 x, float lo, float hi) { return select(x < lo, splat(lo), select(hi < x, splat(hi), x)); }
// Texel indices clamped to [0, n) and wrapped around a row of n, as textures have them
// (lanes::wrap_texel8). The wrap expects [-n, 2n); what is outside it (a NaN coordinate's
// index) the clamp then keeps in the row.
i8 clamp_index(const i8& i, const i8& n) { return lanes::wrap_texel8<false>(i, n, Wrap::Clamp); }
i8 wrap_index(const i8& i, const i8& n) { return clamp_index(lanes::wrap_texel8<false>(i, n, Wrap::Repeat), n); }

// out[k] = base[index[k]], the floats of base by their index.
template <bool Wide>
f8 gather_floats(const float* base, const i8& index) {
    i8 bits;
    lanes::gather<Wide>(reinterpret_cast<const uint32_t*>(base), index, bits);
    f8 out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}
template <bool Wide>
vec3x8 gather_texels(const glm::vec3* texels, const i8& index) {
    const float* base = &texels->x;
    const i8 at = index * 3;
    return {gather_floats<Wide>(base, at), gather_floats<Wide>(base + 1, at), gather_floats<Wide>(base + 2, at)};
}

// atan2(y, x) and acos(c) per lane, as equirect_uv has them: SLEEF's "cinz" functions give
// the same bits for one lane (there), four (SSE2) or eight (AVX). (By reference: see
// lanes::gather.)
template <bool Wide>
void angles(const f8& y, const f8& x, const f8& c, f8& atan2_yx, f8& acos_c) {
    using simd::f4;
    f4 half[2];
    for (int h = 0; h < 2; ++h) {
        f4 yh, xh;
        std::memcpy(&yh, reinterpret_cast<const char*>(&y) + 16 * h, 16);
        std::memcpy(&xh, reinterpret_cast<const char*>(&x) + 16 * h, 16);
        half[h] = f4(Sleef_cinz_atan2f4_u10sse2(__m128(yh), __m128(xh)));
    }
    std::memcpy(&atan2_yx, half, sizeof atan2_yx);
    for (int h = 0; h < 2; ++h) {
        f4 ch;
        std::memcpy(&ch, reinterpret_cast<const char*>(&c) + 16 * h, 16);
        half[h] = f4(Sleef_cinz_acosf4_u10sse2(__m128(ch)));
    }
    std::memcpy(&acos_c, half, sizeof acos_c);
}
#if SOFTRASTER_HAS_AVX2_PATH
// (sleef.h declares its AVX functions only where the whole file is compiled for AVX; here
// only the AVX2 copy is. Declared for AVX: clang refuses a call that passes 32-byte vectors to
// a function compiled without it, as their ABI differs.)
extern "C" [[gnu::target("avx")]] __m256 Sleef_cinz_atan2f8_u10avx(__m256, __m256);
extern "C" [[gnu::target("avx")]] __m256 Sleef_cinz_acosf8_u10avx(__m256);
template <>
[[gnu::target("avx2")]] void angles<true>(const f8& y, const f8& x, const f8& c, f8& atan2_yx, f8& acos_c) {
    atan2_yx = f8(Sleef_cinz_atan2f8_u10avx(__m256(y), __m256(x)));
    acos_c = f8(Sleef_cinz_acosf8_u10avx(__m256(c)));
}
#endif

// Two texels side by side in a row for each lane: left[k] = texels[index[k]], right[k] =
// texels[index[k] + 1] (the caller fixes the lanes whose right texel wrapped to the row's
// start). The array holds two texels past its last (EnvironmentLighting::specular's padding).
template <bool Wide>
void load_pairs(const glm::vec3* texels, const i8& index, vec3x8& left, vec3x8& right) {
    left = gather_texels<Wide>(texels, index);
    right = gather_texels<Wide>(texels, index + 1);
}
#if SOFTRASTER_HAS_AVX2_PATH
// Here one 32-byte load per lane (the pair's six floats and two more) and an 8 x 8 transpose:
// on the lanes' rows r0..r7 of floats (r g b r g b . .), unpacks, shuffles and lane swaps
// give the columns, each one channel of one texel across the lanes. Far cheaper than six gathers.
template <>
[[gnu::target("avx2")]] void load_pairs<true>(const glm::vec3* texels, const i8& index, vec3x8& left, vec3x8& right) {
    const float* base = &texels->x;
    __m256 r[8];
    for (int k = 0; k < 8; ++k) r[k] = _mm256_loadu_ps(base + 3 * size_t(index[k]));
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
    const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
    const __m256 s0 = _mm256_shuffle_ps(t0, t2, 0x44), s1 = _mm256_shuffle_ps(t0, t2, 0xEE);
    const __m256 s2 = _mm256_shuffle_ps(t1, t3, 0x44), s3 = _mm256_shuffle_ps(t1, t3, 0xEE);
    const __m256 s4 = _mm256_shuffle_ps(t4, t6, 0x44), s5 = _mm256_shuffle_ps(t4, t6, 0xEE);
    const __m256 s6 = _mm256_shuffle_ps(t5, t7, 0x44), s7 = _mm256_shuffle_ps(t5, t7, 0xEE);
    // Column c of the rows: s(c) for c < 4 from the low halves, c >= 4 from the high ones.
    left = {f8(_mm256_permute2f128_ps(s0, s4, 0x20)), f8(_mm256_permute2f128_ps(s1, s5, 0x20)), f8(_mm256_permute2f128_ps(s2, s6, 0x20))};
    right = {f8(_mm256_permute2f128_ps(s3, s7, 0x20)), f8(_mm256_permute2f128_ps(s0, s4, 0x31)), f8(_mm256_permute2f128_ps(s1, s5, 0x31))};
}
#endif

vec3x8 select3(const i8& mask, const vec3x8& a, const vec3x8& b) { return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)}; }

vec3x8 mix(const vec3x8& a, const vec3x8& b, const f8& t) {  // a (1 - t) + b t, as glm's vec3 * float
    const f8 s = 1.0f - t;
    return {a.x * s + b.x * t, a.y * s + b.y * t, a.z * s + b.z * t};
}

// The fractional part and whole part of a texel coordinate (the one-lane code's floor). A
// NaN coordinate (a zero normal) gets texel 0 and stays NaN in its weight.
template <bool Wide>
void split(const f8& x, f8& fraction, i8& whole) {
    f8 floor;
    lanes::floor8<Wide>(select(x == x, x, splat(0.0f)), floor);
    fraction = x - floor;
    whole = simd::to_int(floor);
}

// sample_bilinear on each lane's level l of the specular chain (GL_REPEAT across, clamped down).
// Always inline: clang 14's flatten inlines only the entry point's own calls, and with this
// function left out of line (so compiled without AVX) its optimized build's AVX2 copy gave
// wrong lanes (EnvironmentLighting.EightLanesEqualOneAtATimeOnBothPaths). Why is not known:
// its sanitizer build passes, and the copy's AVX2 calls all replaced by the generic ones still
// failed. GCC's flatten inlines it anyway.
template <bool Wide>
[[gnu::always_inline]] inline vec3x8 specular_bilinear(const EnvironmentLighting& e, const i8& l, const f8& u, const f8& v) {
    const i8 w = EnvironmentLighting::kBaseWidth >> l, h = EnvironmentLighting::kBaseHeight >> l;
    constexpr auto at = [](int k) { return EnvironmentLighting::level_offset(std::min(k, EnvironmentLighting::kLevels - 1)); };
    const i8 offsets = {at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7)};
    const i8 offset = simd::permute(offsets, l);
    f8 ax, ay;
    i8 i0, j0;
    split<Wide>(u * simd::to_float(w) - 0.5f, ax, i0);
    split<Wide>(v * simd::to_float(h) - 0.5f, ay, j0);
    // i0 is in [-1, w - 1] for u in [0, 1]: the one-lane code's modulo is one wrap here.
    const i8 left = wrap_index(i0, w), right = wrap_index(i0 + 1, w);
    const i8 top = offset + clamp_index(j0, h) * w, bottom = offset + clamp_index(j0 + 1, h) * w;
    // The two texels of a row side by side in memory, but where the right one wrapped around.
    vec3x8 corner[4];
    load_pairs<Wide>(e.specular.data(), top + left, corner[0], corner[1]);
    load_pairs<Wide>(e.specular.data(), bottom + left, corner[2], corner[3]);
    const i8 wrapped = right != left + 1;
    if (simd::any(wrapped)) {
        corner[1] = select3(wrapped, gather_texels<Wide>(e.specular.data(), top + right), corner[1]);
        corner[3] = select3(wrapped, gather_texels<Wide>(e.specular.data(), bottom + right), corner[3]);
    }
    return mix(mix(corner[0], corner[1], ax), mix(corner[2], corner[3], ax), ay);
}

template <bool Wide>
void light8(const EnvironmentLighting& e, const vec3x8& c_diff, const vec3x8& f0, const vec3x8& n, const vec3x8& v, const f8& nv,
            const f8& roughness, const f8& occlusion, vec3x8& out) {
    // R = reflect(-V, N) and its place in the picture (equirect_uv).
    const f8 twice = 2.0f * simd::dot(n, v);
    const vec3x8 r{twice * n.x - v.x, twice * n.y - v.y, twice * n.z - v.z};
    f8 u, t;
    angles<Wide>(r.x, -r.z, clamp_as_std(r.y, -1.0f, 1.0f), u, t);
    u = 0.5f + u * kInvTwoPi, t = t * kInvPi;

    // A and B (environment_brdf): four texels of the table, clamped to its edges.
    constexpr int kLut = EnvironmentLighting::kLutSize;
    f8 bx, by;
    i8 bi, bj;
    split<Wide>(nv * float(kLut) - 0.5f, bx, bi);
    split<Wide>(roughness * float(kLut) - 0.5f, by, bj);
    const i8 size = splat_i(kLut);
    const i8 row0 = clamp_index(bj, size) * kLut, row1 = clamp_index(bj + 1, size) * kLut;
    const i8 col0 = clamp_index(bi, size), col1 = clamp_index(bi + 1, size);
    const float* lut = &e.lut.data()->x;
    auto lut_at = [&](const i8& k) { return std::array<f8, 2>{gather_floats<Wide>(lut, k * 2), gather_floats<Wide>(lut + 1, k * 2)}; };
    const auto c00 = lut_at(row0 + col0), c10 = lut_at(row0 + col1), c01 = lut_at(row1 + col0), c11 = lut_at(row1 + col1);
    const f8 sx = 1.0f - bx, sy = 1.0f - by;
    const f8 a = (c00[0] * sx + c10[0] * bx) * sy + (c01[0] * sx + c11[0] * bx) * by;
    const f8 b = (c00[1] * sx + c10[1] * bx) * sy + (c01[1] * sx + c11[1] * bx) * by;
    const vec3x8 k{f0.x * a + b, f0.y * a + b, f0.z * a + b};

    // E(N)/pi (environment_irradiance), clamped at 0 as glm::max has it (x < 0 ? 0 : x).
    const std::array<glm::vec3, 9>& c = e.irradiance;
    const f8 xy = n.x * n.y, yz = n.y * n.z, zz = 3.0f * n.z * n.z - 1.0f, xz = n.x * n.z, xx_yy = n.x * n.x - n.y * n.y;
    auto irradiance = [&](auto channel) {
        const f8 sum = channel(c[0]) + channel(c[1]) * n.y + channel(c[2]) * n.z + channel(c[3]) * n.x + channel(c[4]) * xy +
                       channel(c[5]) * yz + channel(c[6]) * zz + channel(c[7]) * xz + channel(c[8]) * xx_yy;
        return select(sum < 0.0f, splat(0.0f), sum);
    };
    const vec3x8 irr{irradiance([](const glm::vec3& q) { return q.x; }), irradiance([](const glm::vec3& q) { return q.y; }),
                     irradiance([](const glm::vec3& q) { return q.z; })};

    // S(R, roughness) (environment_specular): two levels, or the last alone.
    constexpr int kLast = EnvironmentLighting::kLevels - 1;
    const f8 lod = clamp_as_std(roughness * float(kLast), 0.0f, float(kLast));
    const i8 l0 = clamp_index(simd::to_int(select(lod == lod, lod, splat(0.0f))), splat_i(kLast + 1));
    const f8 f = lod - simd::to_float(l0);
    const i8 l1 = select(l0 < kLast, l0 + 1, l0);
    const vec3x8 s0 = specular_bilinear<Wide>(e, l0, u, t);
    vec3x8 s = s0;
    if (simd::any(l0 < kLast)) {
        const vec3x8 s1 = specular_bilinear<Wide>(e, l1, u, t);
        s = select3(l0 >= kLast, s0, mix(s0, s1, f));
    }

    const f8 scale = occlusion * e.intensity;
    auto term = [&](const f8& cd, const f8& ir, const f8& kk, const f8& sp) { return (cd * ir * (1.0f - kk) + sp * kk) * scale; };
    out = {term(c_diff.x, irr.x, k.x, s.x), term(c_diff.y, irr.y, k.y, s.y), term(c_diff.z, irr.z, k.z, s.z)};
}

}  // namespace

void environment_light8(const EnvironmentLighting& e, const simd::vec3x8& c_diff, const simd::vec3x8& f0, const simd::vec3x8& n,
                        const simd::vec3x8& v, const simd::f8& nv, const simd::f8& roughness, const simd::f8& occlusion,
                        simd::vec3x8& out) {
    simd::on_best_path([&]<bool Wide>() { light8<Wide>(e, c_diff, f0, n, v, nv, roughness, occlusion, out); });
}

}  // namespace softraster
