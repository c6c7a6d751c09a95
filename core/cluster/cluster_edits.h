#pragma once
// Edits of a clustering by hand (paper 6, future work: per-panel edits). A designer splits a
// panel in two, merges two neighbouring panels, or holds a group of clusters exactly as they
// are while the rest of the surface is solved again. Each operation keeps the invariants of
// clustering.h (labels in [0, n), every cluster non-empty and edge-connected, seeds inside).
#include <utility>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/flood.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

// Cuts `cluster` in two: seeds at two faces far apart (the face farthest from the cluster's
// centre, then the face farthest from that one, by centroid), grown inside the cluster by the
// metric's flood, so each half is contiguous and fits its own proxy. The new half gets id
// num_clusters() (before the call); both halves are sticky for `sticky_iterations` so the
// next Lloyd steps cannot swallow either. Refits every proxy. The cluster must have at least
// two faces (the caller checks and reports). Returns the new cluster's id.
int split_cluster(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int cluster,
                  int sticky_iterations = 3);

// split_cluster() with the two halves grown from faces a and b of `cluster` (a keeps its id):
// where the caller knows where the cut should go. -1 (nothing changed) unless a and b are
// two distinct faces of the cluster.
int split_cluster_at(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int cluster, int a,
                     int b, int sticky_iterations = 3);

// Merges cluster b into cluster a (they must share an edge: see clusters_share_edge): b's
// faces join a, a keeps its seed, ids above b shift down by one, every proxy is refitted.
// Returns the merged cluster's id after the renumbering.
int merge_clusters(const Metric& metric, Clustering& clustering, int a, int b);

// True when some face of a and some face of b share an edge.
bool clusters_share_edge(const MeshTopology& topology, const std::vector<int>& labels, int a, int b);

// The clusters that share a mesh vertex with `cluster` (itself excluded), sorted: the planes
// that define its panel's nodes.
std::vector<int> cluster_ring(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                              int cluster);

// The worst cluster (highest energy, ties by id) of two faces or more not marked in `keep`,
// or -1: where a panel count increase splits.
int worst_free_cluster(const Metric& metric, const Clustering& clustering, const std::vector<char>& keep);

// The adjacent pair (a < b) of clusters not marked in `keep` whose union costs least, or
// (-1, -1): where a panel count decrease merges.
std::pair<int, int> cheapest_free_merge(const Metric& metric, const MeshTopology& topology,
                                        const Clustering& clustering, const std::vector<char>& keep);

// Another flood cost (the panel phase's boundary term) with given faces kept in given
// clusters (held: per face, its cluster or -1; outlives this): any other assignment of them
// costs kForbidden. Free faces may still join a cluster that holds faces.
class WithHeldFaces : public ExtraCost {
 public:
  WithHeldFaces(const ExtraCost& inner, const std::vector<int>& held) : inner_(inner), held_(held) {}
  double operator()(int face, int k) const override {
    const int h = held_[static_cast<size_t>(face)];
    return h >= 0 && h != k ? kForbidden : inner_(face, k);
  }
  int fixed_label(int face) const override {
    const int h = held_[static_cast<size_t>(face)];
    return h >= 0 ? h : inner_.fixed_label(face);
  }
  static constexpr double kForbidden = 1e30;

 private:
  const ExtraCost& inner_;
  const std::vector<int>& held_;
};

// Keeps given faces in given clusters during a flood (cost 0 otherwise): per face, the
// cluster it must stay in, or -1 when it is free.
class FixedLabels : public ExtraCost {
 public:
  explicit FixedLabels(std::vector<int> fixed) : fixed_(std::move(fixed)) {}
  double operator()(int, int) const override { return 0.0; }
  int fixed_label(int face) const override { return fixed_[static_cast<size_t>(face)]; }

 private:
  std::vector<int> fixed_;
};

}  // namespace ff
