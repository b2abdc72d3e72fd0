// Stage 1, vertex processing: run the vertex shader once per vertex of the buffer.
//
// The results (clip-space position + varyings) form the post-transform vertex buffer that
// primitive assembly indexes into, so a vertex shared by many triangles is shaded once.
#pragma once
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "softraster/pipeline/shader.h"

namespace softraster {

template <int N>
struct ClipVertex {
    glm::vec4 position;        // homogeneous clip coordinates
    std::array<float, N> var;  // varyings
};

template <Shader S>
void process_vertices(const S& shader, std::span<const typename S::Vertex> vertices,
                      std::vector<ClipVertex<kVaryingCount<typename S::Varyings>>>& out) {
    out.resize(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        typename S::Varyings v{};
        out[i].position = shader.vertex(vertices[i], v);
        out[i].var = to_array(v);
    }
}

}  // namespace softraster
