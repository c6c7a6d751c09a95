#pragma once
// Internal to prepare/subdivision: the edges of a polygon mesh with their one or two faces,
// checked to be an oriented edge-manifold, and the crease flags carried from level to level.
#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh/poly_mesh.h"

namespace ff::detail {

// An undirected edge as one sortable number: smaller vertex in the high half.
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b), hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

struct PolyEdges {
  std::vector<std::uint64_t> keys;                 // increasing; edge e joins key >> 32 and key & 0xffffffff
  std::vector<std::array<int, 2>> vertices;        // (smaller, larger)
  std::vector<std::array<int, 2>> faces;           // faces[e][1] == -1 on the boundary
  std::vector<int> corner_edge;                    // corner c (from corners[c] to the next corner) -> edge

  int num_edges() const { return static_cast<int>(keys.size()); }
  bool is_boundary(int e) const { return faces[static_cast<size_t>(e)][1] < 0; }
  // The edge joining a and b, or -1.
  int find(int a, int b) const;
};

// Validates `mesh` (indices in range, faces of 3+ distinct vertices, every edge in at most two
// faces that traverse it in opposite directions) and builds its edges; InputError otherwise.
// `what` names the operation in messages ("subdivision").
PolyEdges build_poly_edges(const PolyMesh& mesh, const char* what);

// Crease flag per edge: boundary edges, plus the edges whose key is in `crease_keys`
// (sorted).
std::vector<char> crease_flags(const PolyEdges& edges, const std::vector<std::uint64_t>& crease_keys);

// The crease keys of the next level: each crease edge e = (a, b) becomes (a, m) and (m, b)
// with m = first_edge_vertex + e. Sorted.
std::vector<std::uint64_t> child_crease_keys(const PolyEdges& edges, const std::vector<char>& crease,
                                             int first_edge_vertex);

}  // namespace ff::detail
