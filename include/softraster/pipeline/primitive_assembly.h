// Stage 2, primitive assembly: group post-transform vertices into triangles, lines, points.
//
// Index buffers are checked once, up front; a primitive with a non-finite clip coordinate
// (a NaN or infinite input position) is dropped here, before it can poison clipping or setup.
#pragma once
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>

#include <glm/vec4.hpp>

namespace softraster {

enum class Topology { Triangles, Lines, Points };

inline int vertices_per_primitive(Topology t) {
    return t == Topology::Triangles ? 3 : t == Topology::Lines ? 2 : 1;
}

inline void validate_indices(std::span<const uint32_t> indices, size_t vertex_count, Topology t) {
    if (indices.size() % size_t(vertices_per_primitive(t)) != 0)
        throw std::invalid_argument("index count is not a multiple of the primitive size");
    for (uint32_t i : indices)
        if (i >= vertex_count) throw std::out_of_range("index past the end of the vertex buffer");
}

inline bool is_finite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

}  // namespace softraster
