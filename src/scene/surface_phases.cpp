// The one copy of the surface shaders' varying-count phases (see record_surface_draw.h).
#include <algorithm>
#include <array>

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
#define SOFTRASTER_CHECK_COUNTS(M) static_assert(counts_listed<Shading::M>(), "add " #M "'s varying counts to SOFTRASTER_SURFACE_VARYING_COUNTS");
SOFTRASTER_SURFACE_MODELS(SOFTRASTER_CHECK_COUNTS)
}  // namespace
}  // namespace softraster
