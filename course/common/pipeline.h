// The course's way into the production pipeline (include/softraster/context.h): a shader
// that takes positions in pixels, so that a lesson can ask the real rasterizer which pixels
// it covers and compare them with its own teaching version.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "softraster/context.h"

namespace course {

// Positions in pixels, (0, 0) the top-left corner of the picture, y down; the shader turns
// them into clip space for a picture of width x height: x_ndc = 2x / width - 1 and
// y_ndc = 1 - 2y / height (the viewport then maps these back to the same pixel positions,
// exactly when width and height are powers of two; otherwise they may come back a rounding
// error off, enough to tip a pixel center lying exactly on an edge to the other side).
struct PixelVertex {
    glm::vec2 position;
};
struct NoVaryings {
    float unused;
};
struct PixelShader {
    using Vertex = PixelVertex;
    using Varyings = NoVaryings;
    float width, height;
    glm::vec4 vertex(const Vertex& in, Varyings& out) const {
        out.unused = 0.0f;
        return {2.0f * in.position.x / width - 1.0f, 1.0f - 2.0f * in.position.y / height, 0.0f, 1.0f};
    }
    bool fragment(const Varyings&, const softraster::FragCoord&, glm::vec4& color) const {
        color = glm::vec4(1.0f);
        return true;
    }
};

// Which pixels the pipeline covers (true) when it draws `positions` as `topology` (one
// sample per pixel, no depth test; culling as asked, triangles counterclockwise as the
// viewer sees them being the front): row-major, width x height.
inline std::vector<bool> pipeline_coverage(int width, int height, softraster::Topology topology, std::span<const PixelVertex> positions,
                                           softraster::CullMode cull = softraster::CullMode::None) {
    softraster::Framebuffer fb(width, height);
    softraster::Context ctx(fb);
    ctx.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    ctx.state.cull = cull;
    ctx.state.depth_test = false;
    std::vector<uint32_t> indices(positions.size());
    for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
    ctx.draw(topology, PixelShader{float(width), float(height)}, positions, std::span<const uint32_t>(indices));
    const softraster::Image picture = ctx.read_pixels();
    std::vector<bool> covered(size_t(width) * size_t(height));
    for (size_t i = 0; i < covered.size(); ++i) covered[i] = picture.pixels[i].r != 0;
    return covered;
}

}  // namespace course
