#pragma once
// NURBS surface -> triangles for the remesher: a grid in parameter space whose sample counts
// follow the surface, span by span (knot spans are never straddled, so kinks at repeated
// knots stay on grid lines), fine enough for a target edge length and a chord tolerance.
// Points that coincide on the grid's border are merged: a closed or periodic surface comes
// out welded along its seam, and a collapsed side (a pole, as on a sphere or a cone tip)
// becomes one vertex, its zero-area triangles dropped.
#include <string>

#include "core/mesh/tri_mesh.h"
#include "core/prepare/nurbs_surface.h"

namespace ff {

struct TessellationOptions {
  double edge_length = 0.0;      // target edge length, model units; must be > 0
  double chord_tolerance = 0.0;  // max sagitta of an edge; <= 0: edge_length / 20
  int max_samples_per_span = 4096;
  long long max_triangles = 4'000'000;  // more throws InputError (the edge length is too small)
};

struct SurfaceTessellation {
  TriMesh mesh;       // oriented like the surface (normals along dS/du x dS/dv)
  int samples_u = 0;  // grid intervals along u and v
  int samples_v = 0;
  int seam_vertices_welded = 0;  // grid-border points merged with a coincident one
  int degenerate_triangles_dropped = 0;
};

// `s` must come from validate_nurbs(). Throws InputError naming `name` when the grid would
// exceed max_triangles or the options are not usable.
SurfaceTessellation tessellate_nurbs(const NurbsSurface& s, const TessellationOptions& options,
                                     const std::string& name);

// The surface's area from a coarse grid (at most 64 x 64 samples plus the knot lines): picks
// an edge length for a triangle budget, e.g. sqrt(2 * area / triangles).
double nurbs_area_estimate(const NurbsSurface& s);

}  // namespace ff
