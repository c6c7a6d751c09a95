#pragma once
// Carrying what a designer attached to one preparation of a surface over to another
// preparation of the same surface (the page re-prepares when the panel count outgrows the
// mesh): per-vertex values (the painted density's log2 levels) by the closest point on the
// old mesh and its barycentric weights, and triangle ids (panel edits name a triangle) by the
// nearest triangle centroid. Both meshes approximate the same surface, so a point of the new
// one lies on or very near the old one.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// values: one per vertex of `from`. Returns one per vertex of `to`: the barycentric
// interpolation of `values` at the point of `from` closest to that vertex. Linear in the
// values, so interpolating log-densities keeps ratios (geometric interpolation of density).
// Throws InputError when the sizes do not match, `from` has no triangles, or a value is not finite.
std::vector<double> transfer_vertex_values(const TriMesh& from, const std::vector<double>& values, const TriMesh& to);

// faces: triangle ids of `from`. Returns for each the id of the triangle of `to` whose
// centroid is nearest to its centroid (ties: the tree's deterministic choice).
// Throws InputError for an id out of range or a `to` without triangles.
std::vector<int> nearest_faces_by_centroid(const TriMesh& from, const std::vector<int>& faces, const TriMesh& to);

}  // namespace ff
