// The one copy of the surface shaders' varying-count phases (see record_surface_draw.h).
#include <algorithm>
#include <array>
#include <tuple>
#include <type_traits>
#include <utility>

#include "scene/record_surface_draw.h"

namespace softraster {
#define SOFTRASTER_DEFINE_SURFACE_PHASES(N) SOFTRASTER_SURFACE_PHASES(N, )
SOFTRASTER_SURFACE_VARYING_COUNTS(SOFTRASTER_DEFINE_SURFACE_PHASES)

// The list of counts is written by hand: a shader whose count it lacks would build its
// phases again in its model's file. Keep it complete.
namespace {
#define SOFTRASTER_COUNT_ENTRY(N) N,
constexpr std::array kListedCounts{SOFTRASTER_SURFACE_VARYING_COUNTS(SOFTRASTER_COUNT_ENTRY)};
template <Shading M>
constexpr bool counts_listed() {
    auto listed = [](int n) { return std::find(kListedCounts.begin(), kListedCounts.end(), n) != kListedCounts.end(); };
    if constexpr (M == Shading::Pbr) {  // (and with a normal map)
        if (!listed(kVaryingCount<typename SurfaceShader<M, true, false, true>::Varyings>) ||
            !listed(kVaryingCount<typename SurfaceShader<M, true, true, true>::Varyings>))
            return false;
    }
    return listed(kVaryingCount<typename SurfaceShader<M, false, false>::Varyings>) &&
           listed(kVaryingCount<typename SurfaceShader<M, true, false>::Varyings>) &&
           listed(kVaryingCount<typename SurfaceShader<M, false, true>::Varyings>) &&
           listed(kVaryingCount<typename SurfaceShader<M, true, true>::Varyings>);
}
// Every surface shader's layout is listed (else its back ends would be compiled again in
// its model's file), once (else twice in the generated files).
template <class L, size_t... K>
constexpr int times_listed(std::index_sequence<K...>) {
    return (0 + ... + int(std::is_same_v<L, std::tuple_element_t<K, SurfaceLayouts>>));
}
template <class S>
constexpr bool listed_once() {
    return times_listed<LayoutOf<S>>(std::make_index_sequence<std::tuple_size_v<SurfaceLayouts>>()) == 1;
}
template <Shading M>
constexpr bool layouts_listed() {
    if constexpr (M == Shading::Pbr)
        if (!listed_once<SurfaceShader<M, true, false, true>>() || !listed_once<SurfaceShader<M, true, true, true>>()) return false;
    return listed_once<SurfaceShader<M, false, false>>() && listed_once<SurfaceShader<M, true, false>>() &&
           listed_once<SurfaceShader<M, false, true>>() && listed_once<SurfaceShader<M, true, true>>();
}
#define SOFTRASTER_CHECK_LAYOUTS(M) static_assert(layouts_listed<Shading::M>(), "add " #M "'s layouts to SOFTRASTER_SURFACE_LAYOUTS");
SOFTRASTER_SURFACE_MODELS(SOFTRASTER_CHECK_LAYOUTS)
#define SOFTRASTER_LISTED_ONCE(M, TEXTURED, COLORED, NORMAL_MAPPED) \
    static_assert(listed_once<SurfaceShader<Shading::M, TEXTURED, COLORED, NORMAL_MAPPED>>(), "a layout listed twice");
SOFTRASTER_SURFACE_LAYOUTS(SOFTRASTER_LISTED_ONCE)
static_assert(std::tuple_size_v<SurfaceLayouts> == 15, "CMakeLists.txt generates a back-end file for each of layouts 1 to 14");
#define SOFTRASTER_CHECK_COUNTS(M) static_assert(counts_listed<Shading::M>(), "add " #M "'s varying counts to SOFTRASTER_SURFACE_VARYING_COUNTS");
SOFTRASTER_SURFACE_MODELS(SOFTRASTER_CHECK_COUNTS)
}  // namespace
}  // namespace softraster
