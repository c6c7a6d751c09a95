// Remesher: per-panel edits (paper 6, future work; DESIGN.md 3). Edits are data in
// RemeshParams::edits, applied in order to the solved design, so a list replays to the same
// panels: undo and redo are a shorter or longer list. Split and merge change the clustering
// and re-run only the panel phase (the Lloyd phase would undo them), with every cluster away
// from the edit settled, so the rest of the design stays as it was. A lock records what the
// panel's outline is made of (its faces and plane, its neighbours' faces and planes, its node
// pairings, the spike distance and D it was laid out with); remesher_locks.cpp turns the
// locks into what the solve holds. Held clusters take no part in later Lloyd steps, count
// changes or splits; a fix that would split one splits a free cluster at its problem corner
// instead.
#include <algorithm>
#include <string>

#include "core/cluster/cluster_edits.h"
#include "core/panels/panel_graph.h"
#include "core/remesher.h"
#include "core/util/error.h"

namespace ff {

namespace {
constexpr size_t kMaxAppliedEdits = 100000;

}  // namespace

const char* edit_name(PanelEdit::Op op) {
  switch (op) {
    case PanelEdit::Op::Split:
      return "split";
    case PanelEdit::Op::Merge:
      return "merge";
    case PanelEdit::Op::Lock:
      return "lock";
    case PanelEdit::Op::Unlock:
      return "unlock";
  }
  return "unknown";
}

struct Remesher::EditState {
  RemeshParams params;
  Clustering clustering;
  Progress progress;
  PanelMesh panels;
  int panel_rounds_done = 0, stalled_rounds = 0, lloyd_done = 0, teleports = 0, retries_done = 0;
  bool converged = false;
  std::vector<char> settled;
  std::vector<Plane> settled_planes, cluster_planes;
  std::vector<CornerNodes> cluster_nodes;
  std::vector<Lock> locks;
  size_t next_edit = 0, base_edits = 0;
  std::shared_ptr<const EditState> base;
};

Remesher::EditState Remesher::save() const {
  return EditState{params_,         clustering_,    progress_,       panels_,  panel_rounds_done_,
                   stalled_rounds_, lloyd_done_,    teleports_,      retries_done_, converged_,
                   settled_,        settled_planes_, cluster_planes_, cluster_nodes_, locks_,
                   next_edit_,      base_edits_,    base_};
}

// Only ever called with a finished design (stage Done), which needs no panel attempt.
void Remesher::restore(const EditState& s) {
  params_ = s.params;
  clustering_ = s.clustering;
  progress_ = s.progress;
  panels_ = s.panels;
  panel_rounds_done_ = s.panel_rounds_done;
  stalled_rounds_ = s.stalled_rounds;
  lloyd_done_ = s.lloyd_done;
  teleports_ = s.teleports;
  retries_done_ = s.retries_done;
  earlier_ = EarlierSolve{};
  converged_ = s.converged;
  settled_ = s.settled;
  settled_planes_ = s.settled_planes;
  cluster_planes_ = s.cluster_planes;
  cluster_nodes_ = s.cluster_nodes;
  locks_ = s.locks;
  next_edit_ = s.next_edit;
  base_edits_ = s.base_edits;
  base_ = s.base;
  best_.reset();
  polish_ = PolishState{};
  coverage_ = CoverageState{};
  needles_ = NeedleState{};
}

void Remesher::clear_edits() {
  locks_.clear();
  base_.reset();
  next_edit_ = 0;
  base_edits_ = 0;
  cluster_planes_.clear();
  cluster_nodes_.clear();
}

void Remesher::validate_edits(const std::vector<PanelEdit>& edits) const {
  if (edits.size() > kMaxAppliedEdits) throw InputError("at most " + std::to_string(kMaxAppliedEdits) + " edits");
  const int faces = mesh_.num_faces();
  for (size_t i = 0; i < edits.size(); ++i) {
    const PanelEdit& e = edits[i];
    const std::string where = "edit " + std::to_string(i + 1) + " (" + edit_name(e.op) + "): ";
    const auto check = [&](int face) {
      if (face < 0 || face >= faces)
        throw InputError(where + "face " + std::to_string(face) + " is out of range (the mesh has " +
                         std::to_string(faces) + " triangles)");
    };
    check(e.face);
    if (e.op == PanelEdit::Op::Merge) check(e.with);
  }
}

void Remesher::record_planes() {
  cluster_planes_ = best_->cluster_planes();
  const PanelLayout& layout = best_->layout();
  cluster_nodes_.assign(cluster_planes_.size(), {});
  for (int c = 0; c < layout.num_clusters(); ++c) cluster_nodes_[static_cast<size_t>(c)] = layout.corner_nodes(c);
}

void Remesher::start_edited_panels(const std::vector<int>& edited) {
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  settled_.assign(n, 1);
  for (int c : edited) {
    settled_[static_cast<size_t>(c)] = 0;
    for (int r : cluster_ring(mesh_, topology_, clustering_.labels, c)) settled_[static_cast<size_t>(r)] = 0;
  }
  settled_planes_ = cluster_planes_;
  settled_planes_.resize(n);
  hold(settled_, settled_planes_);
  best_.reset();
  polish_ = PolishState{};
  coverage_ = CoverageState{};
  needles_ = NeedleState{};
  panel_rounds_done_ = 0;
  stalled_rounds_ = 0;
  progress_ = Progress{Stage::Panels, 0, std::max(1, params_.panel_rounds), progress_.energy, 0};
}

void Remesher::apply_edit(const PanelEdit& e, size_t index) {
  const std::string where = "edit " + std::to_string(index + 1) + " (" + edit_name(e.op) + "): ";
  const std::string at = "the panel at face " + std::to_string(e.face);
  const int n = clustering_.num_clusters();
  if (panels_.num_panels() == 0 || static_cast<int>(cluster_planes_.size()) != n ||
      static_cast<int>(cluster_nodes_.size()) != n)
    throw InputError(where + "there are no panels to edit");
  const std::vector<int>& labels = clustering_.labels;
  const int c = labels[static_cast<size_t>(e.face)];
  const std::vector<char> held = held_clusters();
  // Names the lock in the way, so the designer knows which panel to unlock.
  const auto check_free = [&](int cluster, const std::string& panel) {
    if (held.empty() || !held[static_cast<size_t>(cluster)]) return;
    for (const Lock& lock : locks_) {
      const int locked_face = lock.held[0].face;
      if (labels[static_cast<size_t>(locked_face)] == cluster)
        throw InputError(where + panel + " is locked: unlock it first");
      for (const Held& h : lock.held) {
        if (labels[static_cast<size_t>(h.face)] == cluster)
          throw InputError(where + panel + " is next to the panel locked at face " + std::to_string(locked_face) +
                           ": unlock that first");
      }
    }
    throw InputError(where + panel + " is locked or next to a locked panel: unlock that first");
  };
  const auto find_lock = [&] {
    return std::find_if(locks_.begin(), locks_.end(), [&](const Lock& l) {
      return labels[static_cast<size_t>(l.held[0].face)] == c;
    });
  };
  switch (e.op) {
    case PanelEdit::Op::Split: {
      check_free(c, at);
      if (std::count(labels.begin(), labels.end(), c) < 2)
        throw InputError(where + at + " has a single triangle and cannot be split");
      const int added = split_cluster(metric_, topology_, clustering_, c);
      cluster_planes_.push_back(cluster_planes_[static_cast<size_t>(c)]);
      cluster_nodes_.clear();  // until the next Done; locks need a finished design
      start_edited_panels({c, added});
      break;
    }
    case PanelEdit::Op::Merge: {
      const int d = labels[static_cast<size_t>(e.with)];
      const std::string pair = "faces " + std::to_string(e.face) + " and " + std::to_string(e.with);
      if (c == d) throw InputError(where + pair + " are on the same panel");
      if (!clusters_share_edge(topology_, labels, c, d))
        throw InputError(where + "the panels at " + pair + " are not neighbours (they share no edge)");
      check_free(c, at);
      check_free(d, "the panel at face " + std::to_string(e.with));
      const int merged = merge_clusters(metric_, clustering_, c, d);
      cluster_planes_.erase(cluster_planes_.begin() + d);
      cluster_nodes_.clear();
      start_edited_panels({merged});
      break;
    }
    case PanelEdit::Op::Lock: {
      if (find_lock() != locks_.end()) break;  // locked already
      Lock lock;
      // The clusters around it on the mesh, and every cluster of its outline's nodes: where
      // four clusters meet at a corner, the node pairing can give the panel an edge with a
      // cluster its faces do not touch (nor share a vertex with), whose plane makes two of
      // its corners.
      std::vector<int> clusters = cluster_ring(mesh_, topology_, labels, c);
      const CornerNodes& corners = cluster_nodes_[static_cast<size_t>(c)];
      for (const std::array<int, 3>& t : corners.nodes) {
        for (int k : t) {
          if (k != kBoundary && k != c) clusters.push_back(k);
        }
      }
      for (const std::vector<int>& group : corners.single_groups) {
        for (int k : group) {
          if (k != c) clusters.push_back(k);
        }
      }
      std::sort(clusters.begin(), clusters.end());
      clusters.erase(std::unique(clusters.begin(), clusters.end()), clusters.end());
      clusters.insert(clusters.begin(), c);
      for (int k : clusters) {
        Held h;
        for (size_t f = 0; f < labels.size(); ++f) {
          if (labels[f] == k) h.faces.push_back(static_cast<int>(f));
        }
        h.face = k == c ? e.face : h.faces.front();
        h.plane = cluster_planes_[static_cast<size_t>(k)];
        lock.held.push_back(std::move(h));
      }
      const auto face_of = [&](int cluster) {
        const auto it = std::find(clusters.begin(), clusters.end(), cluster);
        return lock.held[static_cast<size_t>(it - clusters.begin())].face;
      };
      for (const std::vector<int>& group : corners.single_groups) {
        std::vector<int> named;
        for (int k : group) named.push_back(face_of(k));
        lock.single_groups.push_back(std::move(named));
      }
      for (const std::array<int, 3>& t : corners.nodes) {
        std::array<int, 3> named{-1, -1, -1};
        for (size_t k = 0; k < 3; ++k) {
          if (t[k] != kBoundary) named[k] = face_of(t[k]);
        }
        lock.nodes.push_back(named);
      }
      for (const std::vector<int>& vertices : corners.group_vertices) {
        if (vertices.size() == 2)
          lock.grouping.together.emplace_back(std::min(vertices[0], vertices[1]), std::max(vertices[0], vertices[1]));
        else if (vertices.size() == 1)
          lock.grouping.apart.push_back(vertices[0]);
      }
      lock.spike_distance = panels_.spike_distance;
      lock.diameter = metric_.diameter() * faces_.scale;
      locks_.push_back(std::move(lock));
      break;
    }
    case PanelEdit::Op::Unlock: {
      const auto it = find_lock();
      if (it == locks_.end()) throw InputError(where + at + " is not locked");
      locks_.erase(it);
      break;
    }
  }
}

void Remesher::apply_pending_edits() {
  while (progress_.stage == Stage::Done && next_edit_ < params_.edits.size()) {
    if (next_edit_ == base_edits_ && !base_) base_ = std::make_shared<const EditState>(save());
    try {
      apply_edit(params_.edits[next_edit_], next_edit_);
    } catch (...) {
      params_.edits.resize(next_edit_);  // the design stays as it was before this edit
      throw;
    }
    ++next_edit_;
  }
}

bool Remesher::same_solve(const RemeshParams& a, const RemeshParams& b) {
  const MetricWeights &u = a.weights, &v = b.weights;
  return a.panels == b.panels && a.seed == b.seed && u.euclidean == v.euclidean && u.l2 == v.l2 &&
         u.l21 == v.l21 && u.density == v.density && u.boundary == v.boundary && a.density == b.density &&
         a.density_expression == b.density_expression && a.anisotropy == b.anisotropy &&
         a.lloyd_iterations == b.lloyd_iterations && a.seeding == b.seeding &&
         a.teleport_interval == b.teleport_interval && a.teleport_moves == b.teleport_moves &&
         a.make_panels == b.make_panels && a.panel_rounds == b.panel_rounds &&
         a.single_point_nodes == b.single_point_nodes && a.optimize_planes == b.optimize_planes &&
         a.glass == b.glass && a.min_corner_angle_deg == b.min_corner_angle_deg &&
         a.coplanar_angle_deg == b.coplanar_angle_deg && a.retries == b.retries;
}

// The count after edits is the target plus splits minus merges (or what a new count reached):
// asking for either the target or that count is no change, so a page may show the count now
// and send it back unchanged without moving a single panel.
bool Remesher::kept_count(const RemeshParams& params) const {
  if (next_edit_ == 0 || !(params.edits == params_.edits)) return false;
  return params.panels == params_.panels || params.panels == num_panels();
}

void Remesher::set_edits(std::vector<PanelEdit> edits) {
  validate_edits(edits);
  if (!params_.make_panels && !edits.empty()) throw InputError("edits need panels (the panel phase is off)");
  if (!done()) run();
  if (edits == params_.edits) return;
  const EditState before = save();
  const auto starts_with = [&](size_t count) {
    return count <= edits.size() && count <= params_.edits.size() &&
           std::equal(params_.edits.begin(), params_.edits.begin() + static_cast<std::ptrdiff_t>(count), edits.begin());
  };
  try {
    if (starts_with(params_.edits.size())) {
      // More edits: applied to the current design.
    } else if (base_ && starts_with(base_edits_)) {
      const std::shared_ptr<const EditState> base = base_;
      restore(*base);  // undo / redo: from the design before the first edit
      base_ = base;
    } else {  // a fresh solve, as the first (its retries too), then every edit
      clear_edits();
      earlier_ = EarlierSolve{};
      retries_done_ = 0;
      start_over();
    }
    params_.edits = std::move(edits);
    run();
  } catch (...) {
    restore(before);
    throw;
  }
}

}  // namespace ff
