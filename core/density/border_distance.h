#pragma once
// How far each vertex is from the surface's border: the `border` variable of density
// expressions (expression.h), so a designer can ask for smaller panels along the edge of a
// canopy or around a roof's opening, on any shape (u v w only describe the box).
// The nearest border is found over the surface, the distance to it measured straight: the
// boundary edges flood the mesh's vertices (a Dijkstra-style front over its edges) and the
// front carries an edge along, walking the border to the nearest one at each vertex. So a
// vertex's distance is to a segment of the border, not a sum of edge lengths (those
// overestimate by up to 41% across a grid's diagonals), and a surface that folds back on
// itself is not short-cut: a vertex only gets a border the front reached along the surface.
// Never below the straight distance to the nearest boundary edge (it is a distance to one),
// and on the shapes tested equal to it to rounding; above it only where the vertices nearest
// to one edge form a strip narrower than the mesh's edges. About O(V log V): a vertex may be
// lowered a few times, and each visit walks a few border edges.
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

// Per vertex: the straight distance to the nearest boundary edge reached over the surface
// (0 on the border). +infinity where no border can be reached: a closed surface, or a closed
// part of the mesh.
std::vector<double> border_distance(const TriMesh& mesh, const MeshTopology& topology);

}  // namespace ff
