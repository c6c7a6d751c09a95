#pragma once
// The paper's hard cases (Cutler & Whiting 2007, figs. 8, 9, 11) and a few more, as clean
// TriMeshes: no duplicate vertices, edge-manifold, consistently oriented, seams of closed or
// periodic surfaces joined through the index grid (never welded by distance). Open shapes
// have every face normal pointing up (+z); the torus points outward. Sizes are in metres
// with architectural defaults; `triangles` is the approximate triangle count wanted.
// Bad parameters (e.g. an inner radius past the outer one) throw InputError.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/util/angles.h"

namespace ff {

// Saddle (fig. 8): z = rise * (x^2 - y^2) / (size/2)^2 over the square [-size/2, size/2]^2,
// so the edge midpoints sit at +-rise. Negative curvature everywhere. Disk: 1 loop.
TriMesh make_saddle(int triangles, double size = 20.0, double rise = 3.0);

// Helicoid band (fig. 9), a spiral ramp: (r cos t, r sin t, rise_per_turn * t / 2pi) for r
// in [inner_radius, outer_radius], t in [0, 2pi turns]. Ruled, negatively curved. 1 loop.
TriMesh make_helicoid(int triangles, double inner_radius = 4.0, double outer_radius = 10.0, double turns = 1.0,
                      double rise_per_turn = 12.0);

// Twisted strip (fig. 9's "surface twist"): a straight band along x whose straight cross
// sections turn about the x axis from -twist/2 to +twist/2, i.e. a helicoid through its
// axis. Normals stay up while twist < pi. 1 loop.
TriMesh make_twisted_strip(int triangles, double length = 24.0, double width = 6.0, double twist = kPi / 2);

// Bump on a plane (fig. 11): the flat square [-size/2, size/2]^2 with a Gaussian bump
// height * exp(-(x^2 + y^2) / (2 sigma^2)) in the middle. 1 loop.
TriMesh make_bump(int triangles, double size = 20.0, double height = 3.0, double sigma = 2.5);

// Monkey saddle: z = rise * x (x^2 - 3 y^2) / (size/2)^3 over the square [-size/2, size/2]^2.
// Three valleys and three ridges meet at a flat point (zero curvature, the normal turning
// once more around it than a saddle's), so no quadratic fits around the middle. 1 loop.
TriMesh make_monkey_saddle(int triangles, double size = 20.0, double rise = 3.0);

// Conical tent over the square [-size/2, size/2]^2: z = rise * (1 - r / (size/2)), r the
// distance from the z axis; the apex (a mesh vertex) is a point where the normals of every
// direction around the cone meet, the rest is developable (all normals on one cone, as a
// barrel vault's are on one circle). 1 loop.
TriMesh make_cone(int triangles, double size = 20.0, double rise = 6.0);

// Torus around the z axis, outward normals. Closed, genus 1: Euler 0, no loops.
TriMesh make_torus(int triangles, double major_radius = 10.0, double minor_radius = 3.0);

// Groin vault over the square bay [-span/2, span/2]^2: the union of two barrel vaults
// (circular arcs of the given rise) crossing at right angles, z = max(arc(x), arc(y)).
// Its groins (sharp creases) lie on the bay's diagonals, which are edges of the mesh: no
// triangle crosses them. 4 arches spring from the corners (z = 0). 1 loop.
TriMesh make_groin_vault(int triangles, double span = 12.0, double rise = 4.0);

// A gently curved roof over the square [-size/2, size/2]^2 with a round courtyard of the
// given radius cut out of its middle: an annular grid from the hole's circle to the square
// (corners are vertices). 2 loops, Euler 0.
TriMesh make_roof_with_hole(int triangles, double size = 30.0, double hole_radius = 5.0, double rise = 3.0);

// Barrel vault along x: a circular arc of the given span and rise (rise = span / 2 is a
// half cylinder) swept over `length`. Single curvature: every face plane nearly contains
// the x axis, the known-hard case for intersecting three planes. 1 loop.
TriMesh make_barrel_vault(int triangles, double length = 24.0, double span = 12.0, double rise = 6.0);

// A hard case with the topology its mesh must have.
struct NamedShape {
  std::string name;
  TriMesh mesh;
  int boundary_loops = 0;
  int euler_characteristic = 0;
};

// All of the above at their default sizes with about `triangles` triangles each, in this
// order: saddle, helicoid, twisted_strip, bump, torus, groin_vault, roof_with_hole,
// barrel_vault, monkey_saddle, cone.
std::vector<NamedShape> hard_cases(int triangles);

// Grid cells {along u, along v} giving about `triangles` triangles (two per cell) with
// near-square cells on a patch of size length_u x length_v; each count is a positive
// multiple of its `multiple_*` (for symmetric grids and seams).
std::array<int, 2> grid_dims_for(int triangles, double length_u, double length_v, int multiple_u = 1,
                                 int multiple_v = 1);

}  // namespace ff
