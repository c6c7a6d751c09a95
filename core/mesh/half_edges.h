#pragma once
// Internal to core/mesh: the half-edge grouping shared by build_topology() and
// clean_mesh(), and the wording of the errors both report. Not part of the public API.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::detail {

// Half-edge h = 3 * f + i runs from triangles[f][i] to triangles[f][(i + 1) % 3].
inline int tail_of(const std::vector<Triangle>& tris, int h) {
  return tris[static_cast<size_t>(h / 3)][static_cast<size_t>(h % 3)];
}
inline int head_of(const std::vector<Triangle>& tris, int h) {
  return tris[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)];
}
inline int next_in_face(int h) { return h - h % 3 + (h % 3 + 1) % 3; }

// Half-edges grouped by undirected edge. Groups (edges) are numbered in increasing
// (min vertex, max vertex) order and list their half-edges in increasing id order, so the
// numbering depends on the triangles only. Indices must be in range; a repeated vertex
// gives a half-edge from a vertex to itself, grouped like any other.
struct HalfEdgeGroups {
  std::vector<int> order;        // half-edge ids, group by group
  std::vector<int> group_start;  // group g is order[group_start[g] .. group_start[g + 1])
  std::vector<int> edge_of;      // half-edge -> group

  int num_groups() const { return static_cast<int>(group_start.size()) - 1; }
  int group_size(int g) const { return group_start[static_cast<size_t>(g) + 1] - group_start[static_cast<size_t>(g)]; }
  int first(int g) const { return order[static_cast<size_t>(group_start[static_cast<size_t>(g)])]; }
  int second(int g) const { return order[static_cast<size_t>(group_start[static_cast<size_t>(g)]) + 1]; }
};

// O(m + n): counting sort by the smaller vertex, then a small sort per vertex.
HalfEdgeGroups group_half_edges(const std::vector<Triangle>& tris, int num_vertices);

// Throws InputError naming the first (in edge order) edge used by three or more faces and
// how many more there are. vertex_name maps a vertex to the number shown to the user
// (empty: the index itself).
void require_edge_manifold(const HalfEdgeGroups& groups, const std::vector<Triangle>& tris,
                           const std::vector<Vec3>& positions, const std::vector<int>& vertex_name = {});

// Throws InputError for an index outside [0, num_vertices) (and, when require_distinct,
// for a triangle with a repeated vertex).
void require_valid_indices(const std::vector<Triangle>& tris, int num_vertices, bool require_distinct);

// "(x, y, z)" with six significant digits; non-finite values as nan / inf / -inf.
std::string format_point(const Vec3& p);

}  // namespace ff::detail
