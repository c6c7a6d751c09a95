#pragma once
// Closest points on a triangle set: a static AABB tree (median split on the longest axis,
// O(m log m) build) and a pruned nearest-first query. Used by the Hausdorff distance.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// Ericson, Real-Time Collision Detection 5.1.5: the point of triangle abc nearest to p
// (exact for degenerate triangles too: they reduce to an edge or a point).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

struct ClosestPoint {
  double distance = 0.0;  // infinity when the tree is empty
  Vec3 point = Vec3::Zero();
  int triangle = -1;  // index into the triangles the tree was built from
};

class TriangleTree {
 public:
  // Copies what it needs. Throws InputError on an invalid index or a non-finite vertex.
  // Splits are at the centroid median on the longest axis (for large ranges: the nearest
  // boundary of a 256-bin histogram, which keeps the build a few streaming passes per level;
  // 1M triangles in about 0.4 s).
  TriangleTree(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);
  explicit TriangleTree(const TriMesh& mesh) : TriangleTree(mesh.positions, mesh.triangles) {}

  // hint: a triangle likely near q (e.g. the previous query's answer); its distance seeds
  // the pruning bound, which makes coherent query sequences much faster. -1 for none.
  // good_enough > 0: stop at the first triangle found within that distance; the answer is
  // then that triangle, not necessarily the closest (a max-of-min search such as Hausdorff
  // only needs to know a sample is not farther than its current maximum). Exact otherwise.
  // With both, when the hint is not good enough the search first looks in the smallest
  // subtree around the hint whose box holds q (a few levels up, not from the root).
  ClosestPoint closest_point(const Vec3& q, int hint = -1, double good_enough = 0.0) const;

  int num_triangles() const { return static_cast<int>(order_.size()); }

 private:
  struct Node {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    int first = 0;  // leaf: first slot in order_; inner: index of the second child
    int count = 0;  // leaf: number of triangles (> 0); inner: 0 (first child = this + 1)
  };
  struct Item;
  int build(int begin, int end, std::vector<Item>& items);
  void test_triangle(const Vec3& q, int slot, ClosestPoint& best, double& best2) const;
  // Nearest-first search of the subtree at `root`, pruned by best2, until best2 <= enough2.
  void search(const Vec3& q, int root, double enough2, ClosestPoint& best, double& best2) const;

  std::vector<Node> nodes_;
  std::vector<int> order_;  // slot -> original triangle index
  // Per slot, the three corners, stored contiguously in leaf order for locality.
  std::vector<Vec3> corners_;
  std::vector<char> sliver_;  // per slot: a sliver, measured as a segment (closest_point_on_triangle)
  std::vector<int> slot_of_;  // original triangle index -> slot (for hints)
  std::vector<int> parent_;   // per node: its parent (-1 for the root)
  std::vector<int> leaf_of_;  // per slot: the leaf holding it
};

}  // namespace ff
