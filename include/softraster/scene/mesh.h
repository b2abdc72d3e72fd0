// Meshes as the scene format defines them: every vertex has a position, normal, texture
// coordinate and color; triangles, lines and points keep the order of the file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "softraster/pipeline/pipeline_types.h"
#include "softraster/shading/surface_vertex.h"  // MeshVertex, TangentVertex

namespace softraster {

struct Mesh {
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;  // three per triangle
    std::vector<uint32_t> lines;    // two per segment (OBJ `l` elements)
    std::vector<uint32_t> points;   // one per point (OBJ `p` elements)
    // The vertices again with their tangents, for normal-mapped materials only (a mesh drawn
    // without a normal map does not carry them): empty, or one per vertex.
    std::vector<TangentVertex> tangent_vertices;

    size_t triangle_count() const { return indices.size() / 3; }
    // Appends triangle (a, b, c) with fresh corners that all carry its face normal
    // normalize(cross(b - a, c - a)): the rule for triangles without vertex normals.
    void add_face_normal_triangle(MeshVertex a, MeshVertex b, MeshVertex c);
};

// The edges of the triangles, each once (either direction), in the order they first appear:
// two indices per edge.
std::vector<uint32_t> triangle_edges(const Mesh& mesh);
// What an object drawn as `primitive` draws: its triangles; its lines, or if it has none the
// edges of its triangles; its points, or if it has none every vertex.
std::vector<uint32_t> primitive_indices(const Mesh& mesh, Topology primitive);

// Fills mesh.tangent_vertices from the positions, normals and texture coordinates
// (docs/scene-format.md "Normal maps": per triangle, the direction of +u projected into
// each corner's tangent plane, weighted by the corner's angle).
void generate_tangents(Mesh& mesh);

// Loaders. Each throws InputError("<path>:<line>: <what>") for a file it cannot use.
Mesh load_obj(const std::filesystem::path& path);
Mesh load_ply(const std::filesystem::path& path);
// By extension: .obj or .ply.
Mesh load_mesh(const std::filesystem::path& path);

}  // namespace softraster
