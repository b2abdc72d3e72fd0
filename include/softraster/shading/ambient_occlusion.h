// Screen-space ambient occlusion (docs/scene-format.md "Ambient occlusion"): how much of the
// open sky above each pixel's surface its neighbours on screen hide, read from a depth
// buffer of the scene drawn from the camera, and the picture darkened by it. The last
// lesson of tinyrenderer does this with the z-buffer alone; here the depth is turned back
// into view-space positions first, so the radius is in scene units and a flat surface seen
// at a grazing angle stays unoccluded.
//
// For a pixel at view-space position P with normal n (from its neighbours' positions), and
// 16 neighbours Q_i taken from a disk of radius R (scene units) around it on screen:
//   ao = clamp(1 - intensity / 16 * sum_i max(0, n . v_i / |v_i| - bias) * max(0, 1 - |v_i|^2 / R^2), 0, 1)
// with v_i = Q_i - P: a neighbour counts by how far it rises above the surface's tangent
// plane (the cosine, less a bias against the facets of a tessellated curve), fading out
// towards R so that distant geometry does not darken what is in front of it.
#pragma once
#include <array>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "softraster/image.h"
#include "softraster/srgb.h"

namespace softraster {

class WorkerPool;

struct AmbientOcclusionSettings {
    float radius = 0.5f;     // R: scene units around a point that may occlude it
    float intensity = 2.0f;  // how dark a fully hidden point gets, before the clamp
    float bias = 0.1f;       // cosines below this do not occlude
};

inline constexpr int kAmbientOcclusionSamples = 16;

// The sample offsets in the unit disk: a Vogel spiral, point i at radius sqrt((i + 1/2) / 16)
// and angle i times the golden angle pi (3 - sqrt 5), computed in double and rounded to
// float (the llvmpipe reference gets the same table).
const std::array<glm::vec2, kAmbientOcclusionSamples>& ambient_occlusion_kernel();

// The ao factor of each pixel of a width x height depth buffer (row 0 at the top, window
// depth in [0, 1], as Framebuffer keeps it, one sample per pixel) drawn with `projection`;
// 1 where the depth is 1 (nothing drawn). Rows are shared among `pool`'s threads, if any;
// the result does not depend on the thread count.
std::vector<float> ambient_occlusion(const float* depth, int width, int height, const glm::mat4& projection,
                                     const AmbientOcclusionSettings& settings, WorkerPool* pool = nullptr);

// Each pixel's r, g, b times its ao factor: floor(c ao + 1/2) in a linear picture; decoded,
// multiplied and encoded again in an sRGB one. Alpha is kept.
void apply_ambient_occlusion(Image& picture, const std::vector<float>& ao, ColorSpace color);

}  // namespace softraster
