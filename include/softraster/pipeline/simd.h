// Eight lanes of float or int, with GCC/Clang vector extensions: plain arithmetic on them
// compiles to SIMD instructions (two SSE halves on a baseline x86-64 build, one AVX2
// register where the compiler may use AVX2), with no intrinsics in the pipeline's code
// (the few here are where GCC's code for the vector form is poor).
// Used to shade a row of eight pixels at once (fragment_shading.h).
#pragma once
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#if defined(__x86_64__)
#include <emmintrin.h>  // (SSE2, every x86-64 has it: load_bytes, store_bytes)
#endif

namespace softraster::simd {

inline constexpr int kLanes = 8;

// Whether this CPU runs AVX2 and FMA code: the pipeline then takes its AVX2 path
// (on_best_path below), compiled from the same source with those instructions allowed.
// FMA contraction is off (-ffp-contract=off in CMakeLists.txt), so both paths compute
// the same bits and the picture does not depend on the CPU.
// SOFTRASTER_GENERIC=1 in the environment, or use_generic_path(true), forces the other path.
inline std::atomic<bool>& generic_path_forced() {
    static std::atomic<bool> forced{std::getenv("SOFTRASTER_GENERIC") != nullptr};
    return forced;
}
inline void use_generic_path(bool on) { generic_path_forced() = on; }
inline bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return has && !generic_path_forced().load(std::memory_order_relaxed);
#else
    return false;
#endif
}

// Whether this CPU also runs AVX-512 (F, BW, VL, DQ) where the AVX2 path runs: the common
// texture lookup (src/shading/texture_uniform.cpp) then takes a third copy of its own, two
// lanes' texels to a register and its 16-bit filter on 32 lanes, for the same bits.
// SOFTRASTER_NO_AVX512=1 in the environment, or use_avx512(false), keeps it on the AVX2 copy.
inline std::atomic<bool>& avx512_allowed() {
    static std::atomic<bool> allowed{std::getenv("SOFTRASTER_NO_AVX512") == nullptr};
    return allowed;
}
inline void use_avx512(bool on) { avx512_allowed() = on; }
inline bool cpu_has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
                            __builtin_cpu_supports("avx512dq");
    return has && avx512_allowed().load(std::memory_order_relaxed) && cpu_has_avx2();
#else
    return false;
#endif
}

// The AVX2 copy: flatten inlines everything the entry point calls, so the whole loop nest
// really is AVX2 code (a call into an ordinary function would leave it for SSE code). Off in
// sanitizer builds, which it makes very slow to compile. The generic copy is compiled as
// usual: forcing everything inline there costs build time and buys little on CPUs old
// enough to take it.
#ifdef SOFTRASTER_NO_FLATTEN
#define SOFTRASTER_FLATTEN
#else
#define SOFTRASTER_FLATTEN [[gnu::flatten]]
#endif
// SOFTRASTER_GENERIC_ONLY (a development build, CMakeLists.txt): no AVX2 copy at all.
#if (defined(__x86_64__) || defined(__i386__)) && !defined(SOFTRASTER_GENERIC_ONLY)
#define SOFTRASTER_AVX2_TARGET [[gnu::target("avx2,fma")]] SOFTRASTER_FLATTEN
#define SOFTRASTER_HAS_AVX2_PATH 1
#else
#define SOFTRASTER_AVX2_TARGET
#define SOFTRASTER_HAS_AVX2_PATH 0
#endif

// The CPU dispatch, the one place that chooses between the two copies: runs
// f.template operator()<WideLanes>() compiled with AVX2 (WideLanes = true) when the CPU has
// it, else compiled for any x86-64 (false). f is a generic lambda; each caller's lambda is
// compiled twice, once in each copy.
template <class F>
SOFTRASTER_AVX2_TARGET auto run_avx2(const F& f) {
    return f.template operator()<true>();
}
template <class F>
auto run_generic(const F& f) {
    return f.template operator()<false>();
}
// GenericApart: the generic copy out of line, for a small function called very often (a
// texture lookup per eight pixels). Inlined beside the AVX2 call, its stack frame (some
// kilobytes) would be set up on every call of the AVX2 path too.
template <class F>
[[gnu::noinline]] auto run_generic_apart(const F& f) {
    return run_generic(f);
}
inline constexpr bool kGenericApart = true;
// Whether on_best_path runs the AVX2 copy now: this build has one, the CPU runs it, and the
// generic path is not forced.
inline bool wide_path_runs() { return SOFTRASTER_HAS_AVX2_PATH && cpu_has_avx2(); }
template <bool GenericApart = false, class F>
auto on_best_path(const F& f) {
    if (wide_path_runs()) return run_avx2(f);
    if constexpr (GenericApart) return run_generic_apart(f);
    else return run_generic(f);
}

using f8 = float __attribute__((vector_size(32)));
using i8 = int32_t __attribute__((vector_size(32)));  // also the result of comparisons: -1 true, 0 false
// Four lanes, for the steps that have only four values (and the halves of eight).
using f4 = float __attribute__((vector_size(16)));
using i4 = int32_t __attribute__((vector_size(16)));
using u4 = uint32_t __attribute__((vector_size(16)));

// x in every lane, written as a shuffle of lane 0: inside the AVX2 copy (a function with
// target("avx2") that flattens generic code into itself) GCC 12 builds `f8{} + x` from
// inserts or through memory, but a shuffle becomes one vbroadcastss / vpbroadcastd.
inline f8 splat(float x) {
    const f4 v = {x, 0.0f, 0.0f, 0.0f};
    return __builtin_shufflevector(v, v, 0, 0, 0, 0, 0, 0, 0, 0);
}
inline i8 splat_i(int32_t x) {
    const i4 v = {x, 0, 0, 0};
    return __builtin_shufflevector(v, v, 0, 0, 0, 0, 0, 0, 0, 0);
}
inline const i8 kLaneIndex = {0, 1, 2, 3, 4, 5, 6, 7};

// r[k] = v[lanes[k]]: GCC's __builtin_shuffle; clang has no run-time lane shuffle builtin.
template <class V>
inline V permute(V v, i8 lanes) {
#if defined(__clang__)
    V r;
    for (int k = 0; k < kLanes; ++k) r[k] = v[lanes[k]];
    return r;
#else
    return __builtin_shuffle(v, lanes);
#endif
}
inline f8 to_float(i8 v) { return __builtin_convertvector(v, f8); }
inline i8 to_int(f8 v) { return __builtin_convertvector(v, i8); }  // truncates
inline f8 select(i8 mask, f8 a, f8 b) { return mask ? a : b; }
inline i8 select(i8 mask, i8 a, i8 b) { return mask ? a : b; }
inline f8 min(f8 a, f8 b) { return a < b ? a : b; }
inline f8 max(f8 a, f8 b) { return a > b ? a : b; }
inline f8 clamp01(f8 x) { return min(max(x, splat(0.0f)), splat(1.0f)); }  // NaN -> 0
inline f8 sqrt(f8 x) {
    f8 r;
    for (int l = 0; l < kLanes; ++l) r[l] = std::sqrt(x[l]);  // vectorized (-fno-math-errno)
    return r;
}
// any() and bits() take lane masks (each lane all ones or all zeros, as comparisons give)
// and read the lanes' sign bits: on x86 with movmskps, which every x86-64 has (AVX2 code
// gets its VEX form), instead of a reduction through shifts and ors.
#if defined(__x86_64__) || defined(__i386__)
inline bool any(i8 m) {
    i4 lo, hi;
    std::memcpy(&lo, &m, sizeof lo);
    std::memcpy(&hi, reinterpret_cast<const char*>(&m) + sizeof lo, sizeof hi);
    const i4 both = lo | hi;
    f4 f;
    std::memcpy(&f, &both, sizeof f);
    return __builtin_ia32_movmskps(f) != 0;
}
inline unsigned bits(i8 m) {
    f4 lo, hi;
    std::memcpy(&lo, &m, sizeof lo);
    std::memcpy(&hi, reinterpret_cast<const char*>(&m) + sizeof lo, sizeof hi);
    return unsigned(__builtin_ia32_movmskps(lo)) | unsigned(__builtin_ia32_movmskps(hi)) << 4;
}
#else
inline bool any(i8 m) {
    int32_t acc = 0;
    for (int l = 0; l < kLanes; ++l) acc |= m[l];
    return acc != 0;
}
inline unsigned bits(i8 m) {
    unsigned b = 0;
    for (int l = 0; l < kLanes; ++l) b |= unsigned(m[l] & 1) << l;
    return b;
}
#endif

// ---- rows of eight pixels
//
// A span of pixels is walked in groups of eight aligned to multiples of eight in x. Tiles
// are 64 pixels wide, so a group never straddles two tiles and the thread drawing a tile may
// load and store all eight lanes of a group (writing back the old value where a lane is not
// drawn): one unaligned vector load or store each, never a variable-length copy. Only at the
// right edge of an image whose width is not a multiple of eight does a group have fewer than
// eight pixels in memory.

// Calls f(x, lanes) for each group of eight pixels [x, x + 8) that the span [x_begin, x_end)
// touches, `lanes` set for the pixels in the span.
template <class F>
inline void for_each_group(int x_begin, int x_end, F&& f) {
    for (int x = x_begin & ~(kLanes - 1); x < x_end; x += kLanes) {
        const i8 px = kLaneIndex + x;
        f(x, (px >= x_begin) & (px < x_end));
    }
}

// Eight 4-byte values of a row from p[x] on, of which p[x .. width) exist; lanes past the
// end of the row read as zero.
template <class V, class T>
inline V load_group(const T* p, int x, int width) {
    static_assert(sizeof(T) == 4 && sizeof(V) == 4 * kLanes);
    V v{};
    if (x + kLanes <= width) {
        std::memcpy(&v, p + x, sizeof v);
    } else {
        for (int l = 0; l < width - x; ++l) std::memcpy(reinterpret_cast<char*>(&v) + 4 * l, p + x + l, 4);
    }
    return v;
}
// Stores all eight lanes to p[x] on, except those past the end of the row.
template <class V, class T>
inline void store_group(T* p, int x, int width, V v) {
    static_assert(sizeof(T) == 4 && sizeof(V) == 4 * kLanes);
    if (x + kLanes <= width) {
        std::memcpy(static_cast<void*>(p + x), &v, sizeof v);
    } else {
        for (int l = 0; l < width - x; ++l) std::memcpy(static_cast<void*>(p + x + l), reinterpret_cast<const char*>(&v) + 4 * l, 4);
    }
}

// Eight floats from two places, four from each: lanes 0-3 from a, 4-7 from b (two rows of a
// 4x2 block). Two 16-byte loads joined in a register: copied into the halves of a vector in
// memory instead, the vector's one 32-byte load could not take its bytes from the two 16-byte
// stores still on their way to the cache, and waited for them (docs/performance.md, "The 4x2
// blocks' depth in registers"). And back: lanes 0-3 to a, 4-7 to b.
inline f8 load_halves(const float* a, const float* b) {
    f4 low, high;
    std::memcpy(&low, a, sizeof low);
    std::memcpy(&high, b, sizeof high);
    return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
}
inline void store_halves(float* a, float* b, f8 v) {
    const f4 low = __builtin_shufflevector(v, v, 0, 1, 2, 3), high = __builtin_shufflevector(v, v, 4, 5, 6, 7);
    std::memcpy(a, &low, sizeof low);
    std::memcpy(b, &high, sizeof high);
}

// Eight bytes of a row from p[x] on (of which p[x .. width) exist), each widened to a lane;
// lanes past the end of the row read as zero. And back: each lane's low byte stored, except
// past the end. (A stencil row: one 8-byte load or store and a few unpacks or packs, where
// GCC makes eight inserts or extracts of the same conversion written for vectors.)
#if defined(__x86_64__)
inline i8 load_bytes(const uint8_t* p, int x, int width) {
    uint64_t word = 0;
    if (x + kLanes <= width) std::memcpy(&word, p + x, sizeof word);
    else std::memcpy(&word, p + x, size_t(width - x));  // (x86 is little-endian: the first bytes in the lowest lanes)
    const __m128i zero = _mm_setzero_si128(), words = _mm_unpacklo_epi8(_mm_cvtsi64_si128(int64_t(word)), zero);  // (SSE2)
    const i4 lo = i4(_mm_unpacklo_epi16(words, zero)), hi = i4(_mm_unpackhi_epi16(words, zero));
    return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
}
inline void store_bytes(uint8_t* p, int x, int width, i8 v) {
    const i8 low = v & 255;
    const __m128i words = _mm_packs_epi32(__m128i(__builtin_shufflevector(low, low, 0, 1, 2, 3)), __m128i(__builtin_shufflevector(low, low, 4, 5, 6, 7)));
    const auto word = uint64_t(_mm_cvtsi128_si64(_mm_packus_epi16(words, words)));
    if (x + kLanes <= width) std::memcpy(p + x, &word, sizeof word);
    else std::memcpy(p + x, &word, size_t(width - x));
}
#else
inline i8 load_bytes(const uint8_t* p, int x, int width) {
    i8 v{};
    for (int l = 0; l < kLanes && l < width - x; ++l) v[l] = p[x + l];
    return v;
}
inline void store_bytes(uint8_t* p, int x, int width, i8 v) {
    for (int l = 0; l < kLanes && l < width - x; ++l) p[x + l] = uint8_t(v[l]);
}
#endif

// floor(255 clamp(x) + 0.5): the spec's 8-bit conversion, per lane.
inline i8 quantize_unorm8(f8 x) { return to_int(clamp01(x) * 255.0f + 0.5f); }

// Three lanes of f8: a vector per lane, stored by component.
struct vec3x8 {
    f8 x, y, z;
};
// A three-component vector (glm::vec3) in every lane.
template <class V>
inline vec3x8 splat3(const V& v) { return {splat(v.x), splat(v.y), splat(v.z)}; }
inline f8 dot(const vec3x8& a, const vec3x8& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3x8 normalize(const vec3x8& v) {
    const f8 inv = 1.0f / sqrt(dot(v, v));
    return {v.x * inv, v.y * inv, v.z * inv};
}

}  // namespace softraster::simd
