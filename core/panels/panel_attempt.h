#pragma once
// One panel attempt (one round of the panel phase, paper 4): the panel graph of a
// clustering, its master planes, the layout, and the local fixes that need no reclustering
// (pairing switches, spike tilts). Owns copies of what the layout refers to, so an attempt
// can be kept as the best so far while the clustering moves on. Not copyable or movable.
#include <memory>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/panels/panel_layout.h"

namespace ff {

struct PanelAttemptOptions {
  LayoutOptions layout;  // its spike_distance is set from the clusters, see spike_factor
  // A vertex farther from its corner than this times the average cluster diameter is a spike
  // (paper 2.3). The diameter is measured (twice the largest distance from a cluster's
  // centre to its boundary), not D = sqrt(area / n): a regular hexagon is 1.24 D across.
  double spike_factor = 0.2;
  double master_angle_deg = 1.0;
  // Rounds of taking the clusters at spike nodes out of their master planes (each kept only
  // when it leaves fewer invalid panels; PanelLayout::spike_master_clusters).
  int unsnap_rounds = 4;
  int tilt_rounds = 3;
  // Weight of the corners in the planes' fit (plane_fit.h corner_fit_planes); 0: the proxies.
  double corner_weight = 1.0;
  bool relax = true;  // plane_relax.h
  RelaxOptions relax_options;
  // Clusters whose planes are kept from the previous round (their panels and their
  // neighbours' were valid): per cluster, empty for none, and the planes themselves.
  std::vector<char> fixed;
  std::vector<Plane> fixed_planes;
  // Per cluster (empty for none): a fixed cluster whose plane may still turn about the line
  // where it meets the fixed plane of cluster hinge_of[c] (-1: it may not), the neighbour of
  // a locked panel (remesher_edits.cpp). Its master turns when no other fixed cluster is on it.
  std::vector<int> hinge_of;
};

class PanelAttempt {
 public:
  // positions: mesh vertices in the local frame; must outlive the attempt, like mesh and topology.
  // moments: cluster_moments(faces, clustering.labels, n) when the caller has them (nullptr:
  // summed here). graph: build_panel_graph() of clustering.labels when the caller has it
  // (update_panel_graph(), panel_graph_update.h), copied; nullptr: built here.
  PanelAttempt(const TriMesh& mesh, const MeshTopology& topology, const std::vector<Vec3>& positions,
               const FaceData& faces, const Clustering& clustering, const PanelAttemptOptions& options,
               const std::vector<ClusterMoments>* moments = nullptr, const PanelGraph* graph = nullptr);
  PanelAttempt(const PanelAttempt&) = delete;
  PanelAttempt& operator=(const PanelAttempt&) = delete;

  // The last fixes, when the panel rounds are over and this attempt is the best but still
  // has invalid panels (each kept only when fewer panels are invalid): the planes relax
  // again with only the `held` clusters' planes fixed (per cluster, empty for none; the
  // rounds also held the settled ones), the nodes of invalid panels pulled harder each time;
  // then PanelLayout::single_point_fix.
  void mend(const FaceData& faces, const std::vector<char>& held, const PanelAttemptOptions& options);
  // mend() with the orientation judged as at the end (PanelLayout::judge_orientation), kept
  // only when every panel ends valid; otherwise the layout is put back exactly as it was, so
  // the rounds go on as if it had not been tried. Returns whether it was kept.
  bool mend_to_valid(const FaceData& faces, const std::vector<char>& held, const PanelAttemptOptions& options);
  // Whether the planes were already fitted to the surface (Remesher::fit_planes): the
  // finish then does not fit them again.
  bool planes_fitted() const { return planes_fitted_; }
  void set_planes_fitted() { planes_fitted_ = true; }
  // The layout as it is now, for restore(): a trial change (mend_to_valid, the coverage
  // rounds' plane fit) that is not kept is undone exactly.
  struct Saved {
    std::unique_ptr<PanelLayout> layout;
    bool planes_fitted = false;
  };
  Saved save() const;
  void restore(Saved saved);

  const Clustering& clustering() const { return clustering_; }
  const PanelGraph& graph() const { return graph_; }
  // Per cluster: its plane in this attempt (its master's).
  std::vector<Plane> cluster_planes() const;
  // Per cluster: its panel and every panel around it are valid (and, with `coverage`, none
  // of them collapsed).
  std::vector<char> settled_clusters(bool coverage = false) const;
  // Clusters that are not disks get no panel (PanelIssues::not_disk); the rest are laid out.
  PanelLayout& layout() { return *layout_; }
  const PanelLayout& layout() const { return *layout_; }
  // The layout's invalid panels, the clusters that are not disks included.
  int num_invalid() const;

 private:
  Clustering clustering_;
  PanelGraph graph_;
  std::vector<std::pair<int, int>> neighbours_;  // plane_neighbours(), used twice
  double spike_distance_ = 0.0;
  std::unique_ptr<PanelLayout> layout_;
  bool planes_fitted_ = false;
};

// Cluster pairs whose planes meet in the panel mesh: across an edge or at a common corner.
std::vector<std::pair<int, int>> plane_neighbours(const MeshTopology& topology, const std::vector<int>& labels,
                                                  const PanelGraph& graph);

}  // namespace ff
