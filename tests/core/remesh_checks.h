#pragma once
// Checks shared by the remeshing and preparation tests: edge lengths against a target,
// two-sided distance to the input, topology and orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/topology.h"
#include "core/quality/hausdorff.h"
#include "synthetic_meshes.h"  // consistently_oriented
#include "test_meshes.h"

namespace ff::test {

// The edge length whose equilateral triangles tile `mesh` with about `triangles` of them.
inline double edge_length_for(const TriMesh& mesh, double triangles) {
  return std::sqrt(total_area(mesh) / (triangles * std::sqrt(3.0) / 4.0));
}

struct TopologySummary {
  int euler = 0, loops = 0, components = 0;
  bool operator==(const TopologySummary& o) const {
    return euler == o.euler && loops == o.loops && components == o.components;
  }
};

inline TopologySummary summarize(const TriMesh& mesh) {
  const MeshTopology t = build_topology(mesh);
  return {euler_characteristic(mesh, t), static_cast<int>(t.boundary_loops.size()), t.num_components};
}

// Whether any of the messages (a preparation's report, say) contains `word`.
inline bool any_message_says(const std::vector<std::string>& messages, const std::string& word) {
  for (const std::string& m : messages)
    if (m.find(word) != std::string::npos) return true;
  return false;
}

struct EdgeStats {
  int edges = 0;
  int within = 0;  // in [lo, hi] * target
  double min_ratio = 1e300, max_ratio = 0.0;
  double share() const { return edges > 0 ? static_cast<double>(within) / edges : 0.0; }
};

inline EdgeStats edge_stats(const TriMesh& mesh, double target, double lo = 0.6, double hi = 1.5) {
  EdgeStats s;
  std::set<std::pair<int, int>> seen;
  for (const Triangle& t : mesh.triangles) {
    for (size_t i = 0; i < 3; ++i) {
      const int a = std::min(t[i], t[(i + 1) % 3]), b = std::max(t[i], t[(i + 1) % 3]);
      if (!seen.insert({a, b}).second) continue;
      const double r =
          (mesh.positions[static_cast<size_t>(a)] - mesh.positions[static_cast<size_t>(b)]).norm() / target;
      ++s.edges;
      if (r >= lo && r <= hi) ++s.within;
      s.min_ratio = std::min(s.min_ratio, r);
      s.max_ratio = std::max(s.max_ratio, r);
    }
  }
  return s;
}

// Two-sided sampled distance between the surfaces, absolute.
inline double two_sided_distance(const TriMesh& a, const TriMesh& b) {
  return hausdorff_distance(a, b, 20000).two_sided;
}

}  // namespace ff::test
