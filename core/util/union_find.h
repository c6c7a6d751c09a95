#pragma once
// The root of v in a union-find forest (parent[v] == v at a root), halving the path on the
// way: what the mesh clean-up, the manifold part, the part spread and the remesher's crease
// networks use to group vertices or faces.
#include <cstddef>
#include <vector>

namespace ff {

inline int union_find_root(std::vector<int>& parent, int v) {
  while (parent[static_cast<size_t>(v)] != v) {
    parent[static_cast<size_t>(v)] = parent[static_cast<size_t>(parent[static_cast<size_t>(v)])];
    v = parent[static_cast<size_t>(v)];
  }
  return v;
}

}  // namespace ff
