// What each pixel of a scene's picture shows, for data sets: which triangle of which object,
// and that surface's normal at the pixel's center, in full float precision.
//
// The ids come from one more drawing of the scene, with its camera, depth test and culling,
// one sample per pixel and no blending: every triangle drawn unlit in a color that is its
// number (24 bits, the framebuffer's r, g and b). So a pixel's ids name the nearest surface
// at its center, as the depth test decides it. Blended surfaces are drawn as opaque, alpha
// cutoffs are not applied (a cut-out texel counts as surface) and lines and points are left
// out: they are not surfaces.
//
// A normal is the surface's own at the pixel's center: the ray through the center meets the
// triangle's plane at barycentric (b0, b1, b2) (exact and perspective-correct), and
// n = normalize(b0 n0 + b1 n1 + b2 n2) of the world-space vertex normals (the normal matrix
// of the object applied), or the face normal for flat shading, as the shaders use them.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "softraster/scene/scene.h"

namespace softraster {

struct SurfaceIds {
    int width = 0, height = 0;
    std::vector<int32_t> object;    // per pixel, row 0 at the top: index into scene.objects, -1 for none
    std::vector<int32_t> triangle;  // the triangle's index in that object's mesh, -1 for none
};

// The ids of scene's picture (its width x height). Throws InputError past 2^24 - 1 triangles.
SurfaceIds surface_ids(const Scene& scene, unsigned threads = 1);

enum class NormalSpace { World, Camera };  // Camera: OpenCV's axes (x right, y down, z forward)
// Each pixel's unit normal (see above), (0, 0, 0) where ids has no surface.
std::vector<glm::vec3> surface_normals(const Scene& scene, const SurfaceIds& ids, NormalSpace space);

}  // namespace softraster
