#include "scene/record_sky_draw.h"

#include <span>

#include "softraster/context.h"

namespace softraster {

void record_sky_draw(Context& ctx, const SkyShader& shader, const std::array<SkyVertex, 3>& vertices) {
    static constexpr uint32_t kIndices[3] = {0, 1, 2};
    ctx.draw_triangles(shader, std::span<const SkyVertex>(vertices), std::span<const uint32_t>(kIndices));
}

}  // namespace softraster
