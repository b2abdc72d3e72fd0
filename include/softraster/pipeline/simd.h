// Eight lanes of float or int, with GCC/Clang vector extensions: plain arithmetic on them
// compiles to SIMD instructions (two SSE halves on a baseline x86-64 build, one AVX2
// register where the compiler may use AVX2), with no intrinsics in the pipeline's code.
// Used to shade a row of eight pixels at once (fragment_shading.h).
#pragma once
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>

namespace softraster::simd {

inline constexpr int kLanes = 8;

// Whether this CPU runs AVX2 and FMA code: the back end then takes its AVX2 path
// (draw_commands.h), compiled from the same source with those instructions allowed.
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

// flatten: everything the tile loop calls is inlined into it, so the AVX2 copy really is
// AVX2 code throughout (off in sanitizer builds, which it makes very slow to compile).
#ifdef SOFTRASTER_NO_FLATTEN
#define SOFTRASTER_FLATTEN
#else
#define SOFTRASTER_FLATTEN [[gnu::flatten]]
#endif
#if defined(__x86_64__) || defined(__i386__)
#define SOFTRASTER_AVX2_TARGET [[gnu::target("avx2,fma")]] SOFTRASTER_FLATTEN
#define SOFTRASTER_HAS_AVX2_PATH 1
#else
#define SOFTRASTER_AVX2_TARGET SOFTRASTER_FLATTEN
#define SOFTRASTER_HAS_AVX2_PATH 0
#endif
using f8 = float __attribute__((vector_size(32)));
using i8 = int32_t __attribute__((vector_size(32)));  // also the result of comparisons: -1 true, 0 false

inline f8 splat(float x) { return f8{} + x; }
inline i8 splat_i(int32_t x) { return i8{} + x; }
inline const i8 kLaneIndex = {0, 1, 2, 3, 4, 5, 6, 7};

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

// floor(255 clamp(x) + 0.5): the spec's 8-bit conversion, per lane.
inline i8 quantize_unorm8(f8 x) { return to_int(clamp01(x) * 255.0f + 0.5f); }

// Three lanes of f8: a vector per lane, stored by component.
struct vec3x8 {
    f8 x, y, z;
};
inline f8 dot(const vec3x8& a, const vec3x8& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3x8 normalize(const vec3x8& v) {
    const f8 inv = 1.0f / sqrt(dot(v, v));
    return {v.x * inv, v.y * inv, v.z * inv};
}

}  // namespace softraster::simd
