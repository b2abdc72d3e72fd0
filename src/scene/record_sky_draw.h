// Recording the sky's triangle (sky_shader.h), compiled in record_sky_draw.cpp on its own.
#pragma once
#include <array>

#include "softraster/shading/sky_shader.h"

namespace softraster {

class Context;
void record_sky_draw(Context& ctx, const SkyShader& shader, const std::array<SkyVertex, 3>& vertices);

}  // namespace softraster
