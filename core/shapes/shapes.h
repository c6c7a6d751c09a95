#pragma once
// Generated surfaces: examples for the page, hard cases for the tests, inputs of any size for
// the benchmarks. Each is a regular grid over a parameter domain mapped into 3D, with
// triangles oriented so normals follow d/du x d/dv.
#include <functional>

#include "core/mesh/tri_mesh.h"

namespace ff {

// (u, v) in [0,1]^2 -> point. nu x nv quads, each split into two triangles along the
// diagonal alternating in a checkerboard (no directional bias). wrap_u / wrap_v join the
// opposite sides (cylinder, torus).
TriMesh make_grid_surface(int nu, int nv, const std::function<Vec3(double, double)>& map, bool wrap_u = false,
                          bool wrap_v = false);

// A flat rectangle [0,width] x [0,height] in the z = 0 plane.
TriMesh make_plane(int nu, int nv, double width = 1.0, double height = 1.0);

// A smooth double-curved freeform roof over a 40 x 25 footprint (heights 0..8): an
// architectural stand-in for benchmarks at any resolution.
TriMesh make_roof(int nu, int nv);

// Appends quad a-b-c-d (counter-clockwise) as two triangles split along a-c or along b-d.
void add_split_quad(TriMesh& mesh, int a, int b, int c, int d, bool along_ac);

// Number of grid cells per side giving about `triangles` triangles on a square grid.
int grid_resolution_for(int triangles);

}  // namespace ff
