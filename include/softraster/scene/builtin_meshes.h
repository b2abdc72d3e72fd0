// The scene format's generated meshes, by the spec's exact formulas ("Built-in meshes").
// All are centered at the origin, counter-clockwise seen from outside, with normals and uvs.
// Sines and cosines are computed in double precision, then stored as 32-bit floats.
#pragma once
#include "softraster/scene/mesh.h"

namespace softraster {

Mesh make_plane(double size, int divisions);
Mesh make_uv_sphere(double radius, int rings, int segments);
Mesh make_torus(double major, double minor, int rings, int segments);
Mesh make_cube(double size);

}  // namespace softraster
