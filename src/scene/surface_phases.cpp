// The one copy of the surface shaders' varying-count phases (see record_surface_draw.h).
#include "scene/record_surface_draw.h"

namespace softraster {
#define SOFTRASTER_DEFINE_SURFACE_PHASES(N) SOFTRASTER_SURFACE_PHASES(N, )
SOFTRASTER_SURFACE_VARYING_COUNTS(SOFTRASTER_DEFINE_SURFACE_PHASES)
}  // namespace softraster
