#pragma once
// Helpers shared by the clustering tests: loading a cleaned shared mesh, the invariants every
// clustering must keep, and test-name sanitising.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "core/cluster/clustering.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "test_meshes.h"

namespace ff::test {

// Labels in [0, n), every cluster non-empty and edge-connected, seeds distinct and inside
// their own cluster, one proxy and one stickiness counter per cluster.
inline ::testing::AssertionResult keeps_invariants(const MeshTopology& topology, const Clustering& c, int n) {
  if (c.num_clusters() != n) return ::testing::AssertionFailure() << c.num_clusters() << " clusters, expected " << n;
  if (c.seeds.size() != static_cast<size_t>(n) || c.sticky.size() != static_cast<size_t>(n))
    return ::testing::AssertionFailure() << "seeds/sticky sizes " << c.seeds.size() << "/" << c.sticky.size();
  if (!clusters_are_contiguous(topology, c.labels, n))
    return ::testing::AssertionFailure() << "a cluster is empty, disconnected or a label is out of range";
  if (std::set<int>(c.seeds.begin(), c.seeds.end()).size() != c.seeds.size())
    return ::testing::AssertionFailure() << "two clusters share a seed";
  for (int i = 0; i < n; ++i) {
    if (c.labels[static_cast<size_t>(c.seeds[static_cast<size_t>(i)])] != i)
      return ::testing::AssertionFailure() << "seed of cluster " << i << " lies outside it";
  }
  return ::testing::AssertionSuccess();
}

inline std::string test_name(std::string s) {
  std::replace_if(
      s.begin(), s.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return s;
}

}  // namespace ff::test
