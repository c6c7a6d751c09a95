#include "core/panels/panel_attempt.h"

#include <algorithm>

#include <Eigen/Dense>

#include "core/panels/plane_fit.h"

namespace ff {

namespace {

std::vector<Plane> proxy_planes(const Clustering& clustering) {
  std::vector<Plane> planes;
  for (const Proxy& p : clustering.proxies) planes.push_back(Plane::through(p.center, p.normal));
  return planes;
}

// Per master: whether a fixed (settled) cluster is on it; empty when none is fixed.
std::vector<char> fixed_masters_of(const PanelLayout& layout, const std::vector<char>& fixed) {
  std::vector<char> out;
  if (fixed.empty()) return out;
  out.assign(layout.planes().planes.size(), 0);
  for (size_t c = 0; c < fixed.size() && c < layout.planes().master_of.size(); ++c) {
    if (fixed[c]) out[static_cast<size_t>(layout.planes().master_of[c])] = 1;
  }
  return out;
}

// Per master: the line it may turn about (PanelAttemptOptions::hinge_of), freeing it in
// `fixed_masters`. A master turns only when every fixed cluster on it is hinged on the same
// line (its plane is theirs) and the line is well defined (the planes cross at a clear angle).
std::vector<PlaneHinge> master_hinges(const PanelLayout& layout, const std::vector<char>& fixed,
                                      const std::vector<int>& hinge_of, std::vector<char>& fixed_masters) {
  std::vector<PlaneHinge> out;
  if (hinge_of.empty() || fixed_masters.empty()) return out;
  const MasterPlanes& planes = layout.planes();
  out.assign(planes.planes.size(), PlaneHinge{});
  std::vector<int> axis(planes.planes.size(), -1);  // per master: the hinge cluster, -2: none possible
  for (size_t c = 0; c < fixed.size() && c < planes.master_of.size(); ++c) {
    if (!fixed[c]) continue;
    const size_t m = static_cast<size_t>(planes.master_of[c]);
    const int h = c < hinge_of.size() ? hinge_of[c] : -1;
    const bool same = h >= 0 && (axis[m] == -1 || axis[m] == h);
    axis[m] = same ? h : -2;
  }
  constexpr double kMinSine = 0.02;  // about 1.1 degrees, beyond the master planes' angle
  for (size_t m = 0; m < axis.size(); ++m) {
    if (axis[m] < 0) continue;
    const size_t other = static_cast<size_t>(planes.master_of[static_cast<size_t>(axis[m])]);
    if (other == m) continue;
    const Plane& a = planes.planes[m];
    const Plane& b = planes.planes[other];
    const Vec3 line = a.normal.cross(b.normal);
    if (!(line.norm() > kMinSine)) continue;
    // The point of the line nearest the master's centre.
    Eigen::Matrix3d A;
    A.row(0) = a.normal.transpose(), A.row(1) = b.normal.transpose(), A.row(2) = line.normalized().transpose();
    const Vec3 point = A.colPivHouseholderQr().solve(Vec3(a.offset, b.offset, line.normalized().dot(planes.centers[m])));
    if (!point.allFinite()) continue;
    out[m] = PlaneHinge{true, point, line.normalized()};
    fixed_masters[m] = 0;
  }
  return out;
}

// Relaxes the layout's planes (plane_relax.h), then, once some planes are held, the paper's
// tilt (2.3) in the same least squares: pull the spikes harder and relax again, for as long
// as that lowers the number of invalid panels. Masters with a fixed cluster stay, or only
// turn about their hinge.
void relax(PanelLayout& layout, const std::vector<ClusterMoments>& moments, const std::vector<char>& fixed,
           const PanelAttemptOptions& options) {
  const size_t n = moments.size();
  std::vector<ClusterMoments> master_moments(layout.planes().planes.size());
  for (size_t c = 0; c < n; ++c) master_moments[static_cast<size_t>(layout.planes().master_of[c])].add(moments[c]);
  std::vector<char> fixed_masters = fixed_masters_of(layout, fixed);
  const std::vector<PlaneHinge> hinges = master_hinges(layout, fixed, options.hinge_of, fixed_masters);
  std::vector<NodeConstraint> nodes = layout.node_constraints();
  layout.set_planes(
      relax_planes(nodes, master_moments, layout.planes().planes, options.relax_options, fixed_masters, hinges));
  // Not while no plane is held (a first round): there every plane is free, so a tilt costs
  // a whole relaxation, the most expensive step of the round, for a fifth of the time a few
  // invalid panels fewer (32 of 141 tilts kept on 13 shared meshes, 60-200 panels), which
  // the next rounds fix anyway. Measured over the validity sweep, seeds 1-12: valid 766
  // against 767 of 768 runs (cow 46 at seeds 1-24: 20 against 19 of 24), panel rounds 8852
  // against 8925, the panel phase 10% faster. Later rounds relax only the planes not held.
  const int tilts = fixed.empty() ? 0 : options.tilt_rounds;
  for (int t = 0; t < tilts && layout.num_invalid() > 0; ++t) {
    // Spikes, and every node of a panel that is invalid otherwise (a flipped edge is two
    // nodes in the wrong order: pulled to their corners they come back in order).
    std::vector<char> pull = layout.spike_nodes();
    for (int c = 0; c < layout.num_clusters(); ++c) {
      if (layout.issues()[static_cast<size_t>(c)].valid()) continue;
      for (int node : layout.polygon(c).node) {
        if (node >= 0) pull[static_cast<size_t>(node)] = 1;
      }
    }
    if (std::find(pull.begin(), pull.end(), 1) == pull.end()) break;
    for (size_t k = 0; k < nodes.size(); ++k) nodes[k].weight *= pull[k] ? 10.0 : 1.0;
    const std::vector<Plane> before = layout.planes().planes;
    const int invalid = layout.num_invalid();
    layout.set_planes(relax_planes(nodes, master_moments, before, options.relax_options, fixed_masters, hinges));
    if (layout.num_invalid() >= invalid) {
      layout.set_planes(before);
      break;
    }
  }
}

}  // namespace

PanelAttempt::PanelAttempt(const TriMesh& mesh, const MeshTopology& topology, const std::vector<Vec3>& positions,
                           const FaceData& faces, const Clustering& clustering, const PanelAttemptOptions& options,
                           const std::vector<ClusterMoments>* known_moments, const PanelGraph* graph)
    : clustering_(clustering),
      graph_(graph ? *graph : build_panel_graph(mesh, topology, clustering_.labels, clustering_.num_clusters())) {
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  // Average cluster diameter, from the cluster boundaries.
  std::vector<double> reach(n, 0.0);
  for (size_t f = 0; f < clustering_.labels.size(); ++f) {
    const size_t c = static_cast<size_t>(clustering_.labels[f]);
    for (int v : mesh.triangles[f]) {
      reach[c] = std::max(reach[c], (positions[static_cast<size_t>(v)] - clustering_.proxies[c].center).norm());
    }
  }
  double sum = 0.0;
  for (double r : reach) sum += 2.0 * r;
  spike_distance_ = options.spike_factor * sum / static_cast<double>(std::max<size_t>(n, 1));
  std::vector<std::vector<Vec3>> corners(n);
  {  // Counted first: one allocation per cluster.
    std::vector<int> count(n, 0);
    for (const Corner& corner : graph_.corners) {
      for (int c : corner.clusters) {
        if (c != kBoundary) ++count[static_cast<size_t>(c)];
      }
    }
    for (size_t c = 0; c < n; ++c) corners[c].reserve(static_cast<size_t>(count[c]));
  }
  std::vector<Vec3> orientation(n), centers(n);
  for (const Corner& corner : graph_.corners) {
    for (int c : corner.clusters) {
      if (c != kBoundary) corners[static_cast<size_t>(c)].push_back(positions[static_cast<size_t>(corner.vertex)]);
    }
  }
  for (size_t c = 0; c < n; ++c) orientation[c] = clustering_.proxies[c].normal;
  std::vector<ClusterMoments> summed;
  if (!known_moments || known_moments->size() != n)
    summed = cluster_moments(faces, clustering_.labels, static_cast<int>(n));
  const std::vector<ClusterMoments>& moments = known_moments && known_moments->size() == n ? *known_moments : summed;
  std::vector<Plane> planes = options.corner_weight > 0.0
                                  ? corner_fit_planes(moments, corners, orientation, options.corner_weight)
                                  : proxy_planes(clustering_);
  const bool any_fixed = std::find(options.fixed.begin(), options.fixed.end(), 1) != options.fixed.end();
  for (size_t c = 0; c < n && c < options.fixed.size() && c < options.fixed_planes.size(); ++c) {
    if (options.fixed[c]) planes[c] = options.fixed_planes[c];
  }
  std::vector<double> areas(n, 0.0);  // local frame: no overflow at any scale
  for (size_t c = 0; c < n; ++c) {
    centers[c] = planes[c].project(clustering_.proxies[c].center);
    areas[c] = moments[c].area;
  }
  neighbours_ = plane_neighbours(topology, clustering_.labels, graph_);
  LayoutOptions layout_options = options.layout;
  layout_options.spike_distance = spike_distance_;
  const std::vector<char> no_fixed;
  const std::vector<char>& fixed = any_fixed ? options.fixed : no_fixed;
  // Planes, relaxed (plane_relax.h), for one choice of master planes.
  const auto lay_out = [&](const std::vector<char>& alone) {
    MasterPlanes masters =
        snap_master_planes(planes, centers, areas, neighbours_, options.master_angle_deg, fixed, alone);
    // With the relaxation the panels are built once, on its planes (not also on these).
    auto layout =
        std::make_unique<PanelLayout>(mesh, topology, clustering_.labels, positions, graph_, std::move(masters),
                                      layout_options, std::vector<std::pair<int, int>>{}, !options.relax);
    if (options.relax) relax(*layout, moments, fixed, options);
    return layout;
  };
  layout_ = lay_out({});
  // Spikes at nodes where a plane is a master shared by several clusters: on a barrel vault,
  // strips of panels along the axis snap into one master each, and where a strip ends
  // between two others all three planes nearly contain the axis, so their point runs off
  // along it; a whole strip cannot tilt without leaving its faces. The cluster at the
  // strip's end can: take the clusters at such nodes out of their masters (the paper's
  // "snap/unsnap facets to master planes", 4) and relax again; kept when fewer panels are
  // invalid.
  std::vector<char> alone(n, 0);
  for (int t = 0; t < options.unsnap_rounds && layout_->num_invalid() > 0; ++t) {
    bool more = false;
    const std::vector<char> spiked = layout_->spike_master_clusters();
    for (size_t c = 0; c < n; ++c) {
      if (spiked[c] && !alone[c]) alone[c] = 1, more = true;
    }
    if (!more) break;
    auto unsnapped = lay_out(alone);
    if (unsnapped->num_invalid() >= layout_->num_invalid()) break;
    layout_ = std::move(unsnapped);
  }
  layout_->switch_pairings();
  // Flipped edges between two nodes: group their corners and let the pairing choose again
  // (paper fig. 6, "switching the neighbour assignments"), with the planes as they are now.
  std::vector<std::pair<int, int>> forced;
  for (int t = 0; t < 2 && layout_->num_invalid() > 0; ++t) {
    const std::vector<std::pair<int, int>> reversed = layout_->reversed_chains();
    const size_t before = forced.size();
    for (const auto& pair : reversed) {
      if (std::find(forced.begin(), forced.end(), pair) == forced.end()) forced.push_back(pair);
    }
    if (forced.size() == before) break;
    auto regrouped = std::make_unique<PanelLayout>(mesh, topology, clustering_.labels, positions, graph_,
                                                   layout_->planes(), layout_options, forced);
    regrouped->switch_pairings();
    if (regrouped->num_invalid() >= layout_->num_invalid()) break;
    layout_ = std::move(regrouped);
  }
  for (int t = 0; t < options.tilt_rounds && layout_->num_invalid() > 0; ++t) {
    std::vector<char> fixed_masters = fixed_masters_of(*layout_, fixed);
    const std::vector<PlaneHinge> hinges = master_hinges(*layout_, fixed, options.hinge_of, fixed_masters);
    if (!layout_->tilt_spike_planes(fixed_masters, hinges)) break;
    layout_->switch_pairings();
  }
}

bool PanelAttempt::mend_to_valid(const FaceData& faces, const std::vector<char>& held,
                                 const PanelAttemptOptions& options) {
  Saved saved = save();
  layout_->judge_orientation();
  mend(faces, held, options);
  if (num_invalid() == 0) return true;
  restore(std::move(saved));
  return false;
}

PanelAttempt::Saved PanelAttempt::save() const {
  return Saved{std::make_unique<PanelLayout>(*layout_), planes_fitted_};
}

void PanelAttempt::restore(Saved saved) {
  layout_ = std::move(saved.layout);
  planes_fitted_ = saved.planes_fitted;
}

void PanelAttempt::mend(const FaceData& faces, const std::vector<char>& held, const PanelAttemptOptions& options) {
  PanelLayout& layout = *layout_;
  if (layout.num_invalid() == 0) return;
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  const std::vector<char> fixed_masters = fixed_masters_of(layout, held);
  if (options.relax) {
    // The rounds held the planes of settled clusters; now every plane but the held ones may
    // move, and the nodes of the invalid panels pull harder each time (as in relax()).
    const std::vector<ClusterMoments> moments = cluster_moments(faces, clustering_.labels, static_cast<int>(n));
    std::vector<ClusterMoments> master_moments(layout.planes().planes.size());
    for (size_t c = 0; c < n; ++c) master_moments[static_cast<size_t>(layout.planes().master_of[c])].add(moments[c]);
    std::vector<NodeConstraint> nodes = layout.node_constraints();
    const std::vector<Plane> start = layout.planes().planes;
    std::vector<Plane> best = start;
    int best_invalid = layout.num_invalid();
    for (int t = 0; t < options.tilt_rounds + 1 && best_invalid > 0; ++t) {
      std::vector<char> pull = layout.spike_nodes();
      for (int c = 0; c < layout.num_clusters(); ++c) {
        if (layout.issues()[static_cast<size_t>(c)].valid()) continue;
        for (int node : layout.polygon(c).node) {
          if (node >= 0) pull[static_cast<size_t>(node)] = 1;
        }
      }
      for (size_t k = 0; k < nodes.size(); ++k) nodes[k].weight *= pull[k] ? 10.0 : 1.0;
      layout.set_planes(relax_planes(nodes, master_moments, start, options.relax_options, fixed_masters));
      if (layout.num_invalid() < best_invalid) best_invalid = layout.num_invalid(), best = layout.planes().planes;
    }
    layout.set_planes(best);
    if (layout.num_invalid() > 0) layout.switch_pairings();
  }
  // Nodes whose planes nearly share a line: one plane at a time aimed at the node.
  for (int t = 0; t < 2 && layout.num_invalid() > 0; ++t) {
    if (layout.aim_node_planes(fixed_masters) == 0) break;
  }
  // Short edges whose two nodes came out in the wrong order with no spike to aim at.
  if (layout.num_invalid() > 0 && layout.aim_edge_order(fixed_masters) > 0) layout.switch_pairings();
  // Planes turned across their faces (misoriented panels).
  if (layout.num_invalid() > 0 && layout.aim_face_normals(fixed_masters) > 0) layout.switch_pairings();
  layout.single_point_fix(fixed_masters);
}

std::vector<Plane> PanelAttempt::cluster_planes() const {
  std::vector<Plane> out;
  for (int c = 0; c < clustering_.num_clusters(); ++c) out.push_back(layout_->planes().plane_of(c));
  return out;
}

std::vector<char> PanelAttempt::settled_clusters(bool coverage) const {
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  std::vector<char> valid(n, 0);
  for (size_t c = 0; c < n; ++c)
    valid[c] = layout_->issues()[c].valid() && !(coverage && layout_->issues()[c].collapsed);
  std::vector<char> settled = valid;
  for (const auto& [a, b] : neighbours_) {
    if (!valid[static_cast<size_t>(a)]) settled[static_cast<size_t>(b)] = 0;
    if (!valid[static_cast<size_t>(b)]) settled[static_cast<size_t>(a)] = 0;
  }
  return settled;
}

int PanelAttempt::num_invalid() const { return layout_->num_invalid(); }

std::vector<std::pair<int, int>> plane_neighbours(const MeshTopology& topology, const std::vector<int>& labels,
                                                  const PanelGraph& graph) {
  std::vector<std::pair<int, int>> pairs = adjacent_cluster_pairs(topology, labels);
  for (const Corner& corner : graph.corners) {
    for (size_t i = 0; i < corner.clusters.size(); ++i) {
      for (size_t j = i + 1; j < corner.clusters.size(); ++j) {
        const int a = corner.clusters[i], b = corner.clusters[j];
        if (a == kBoundary || b == kBoundary || a == b) continue;
        pairs.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace ff
