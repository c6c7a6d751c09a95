// Remesher: more attempts from the best one, when the panel rounds and mend_best() leave it
// invalid (issue 3, cow.off at seed 2). The rounds' invalid count jumps about (on the cow at
// 61 panels between 3 and 31 from round to round), so the best round is the luckiest sample
// of a random walk: its problems get a split and a Lloyd step like any other round's, but
// split_near() merges a pair elsewhere and the step refloods every unsettled cluster, so the
// next round has 9 invalid panels and the run walks away from it. mend() cannot split.
// Here the clustering goes back to the best attempt's and only its problems change: each
// split request of split_requests() on it is a local cut (split_cluster_at: the cluster's
// seed and the requested face grow inside the cluster, nothing else refloods), paid for by
// merging the cheapest pair of clusters away from every invalid panel and its neighbours
// (so n stays), the settled planes kept. That attempt is mended like the best, then a few
// rounds chain from it while it stays close to the best; kept only with fewer invalid
// panels. Three passes: the splits of clusters that are not disks only, then near every
// invalid panel too, then (third) each invalid panel's cluster cut in two along its length
// (split_cluster). cow.off at 100 panels, seed 7, ends valid in the second pass's first
// attempt (a split near its problem), at 78, seed 6, in the third; at 61, seed 2, the
// first pass cuts the two clusters that meet a neighbour twice, 5 panels are invalid after
// the mend and 1 a round later (was 2). (face.obj at 574, seed 2, ended valid in the third
// pass, a plane 94 degrees from its faces that aim_face_normals could not turn back, until
// the early mend stopped at 3 invalid panels: its rounds now end valid.) Not enough for
// cow.off at 46, seed 2 (2 invalid). Runs that end valid never get
// here, so they are unchanged; the others take up to 18 more attempts, one per step() (a
// panel round and a mend each: the worker stays as responsive as in the rounds), with the
// progress of the panel stage (its round count stays, the invalid count is the best's).
// Not with locked panels (held clusters are numbered in the clustering of the moment).
#include <algorithm>
#include <memory>
#include <utility>

#include "core/cluster/cluster_edits.h"
#include "core/panels/panel_graph.h"
#include "core/panels/split_requests.h"
#include "core/remesher.h"

namespace ff {

namespace {
// More attempts per pass at most; each costs about one panel round and its mend (a step).
constexpr int kPolishAttempts = 6;
constexpr int kPolishMargin = 3;  // on the cow at 61: 5 invalid (best 2), then 1
constexpr int kMergeTries = 12;   // candidate merges per pass, at most
constexpr int kPolishPasses = 3;
}  // namespace

bool Remesher::start_polish() {
  polish_ = PolishState{};
  if (!locks_.empty() || !best_ || best_->num_invalid() == 0) return false;
  polish_.active = true;
  return true;
}

// Three passes: splitting only the clusters that are not disks, then near every problem too,
// then every invalid panel's cluster cut in two along its length. Each step() mends one
// attempt (a pass's first, or the next round of its chain); a pass whose splits or merges
// cannot be made costs no attempt and the next one starts in the same step.
void Remesher::polish_step() {
  PolishState& s = polish_;
  std::unique_ptr<PanelAttempt> attempt;
  while (!attempt) {
    if (s.chain) {
      // A chain of rounds (the boundary term; splits only where clusters are not disks) while
      // close to the best: far behind, the rounds have walked away from it.
      const PanelAttempt& from = s.from ? *s.from : *best_;
      clustering_ = from.clustering();
      stalled_rounds_ = 0;
      fix_panels(from);
      s.chain = false;
      attempt = make_attempt();
      s.from.reset();
    } else if (s.pass < kPolishPasses && best_->num_invalid() > 0) {
      const int pass = s.pass++;
      s.attempts = 0;
      attempt = polish_pass(pass == 0 ? 0 : pass == 1 ? best_->num_invalid() : -1);
    } else {
      break;
    }
  }
  if (attempt) {
    attempt->layout().judge_orientation();
    attempt->mend(faces_, {}, PanelAttemptOptions{});
    const bool better = attempt->num_invalid() < best_->num_invalid();
    if (better) std::swap(best_, attempt);  // attempt: the old best, dropped
    progress_.invalid_panels = best_->num_invalid();
    ++s.attempts;
    const PanelAttempt& from = better ? *best_ : *attempt;
    s.chain = s.attempts < kPolishAttempts && best_->num_invalid() > 0 &&
              from.num_invalid() <= best_->num_invalid() + kPolishMargin;
    if (s.chain && !better) s.from = std::move(attempt);
    if (!s.chain) clustering_ = best_->clustering();  // the pass ends
    // More to try: the next step. Otherwise the panel phase ends in this one.
    if (s.chain || (s.pass < kPolishPasses && best_->num_invalid() > 0)) return;
  }
  clustering_ = best_->clustering();
  polish_ = PolishState{};
  end_panels();
}

std::unique_ptr<PanelAttempt> Remesher::polish_pass(int max_geometric) {
  clustering_ = best_->clustering();
  settled_ = best_->settled_clusters();
  settled_planes_ = best_->cluster_planes();
  // Kept out of the merges: the invalid panels, everything whose plane meets theirs, and
  // every cluster next to a split.
  std::vector<char> keep(settled_.size(), 0);
  for (size_t c = 0; c < settled_.size(); ++c) keep[c] = !settled_[c];
  std::vector<std::pair<int, int>> requests;
  if (max_geometric >= 0)
    requests = split_requests(mesh_, topology_, *best_, cluster_cuts(mesh_, topology_, *best_).cuts, max_geometric);
  // An invalid panel with no problem corner to split at is cut in two along its length
  // (face -1), and in the last pass (max_geometric -1) every invalid panel is (a plane turned
  // 94 degrees from its faces: face.obj at 574 panels, seed 2, once ended valid so).
  for (int c = 0; max_geometric != 0 && c < best_->layout().num_clusters(); ++c) {
    if (best_->layout().issues()[static_cast<size_t>(c)].valid()) continue;
    const auto has = [c](const std::pair<int, int>& r) { return r.first == c; };
    if (std::none_of(requests.begin(), requests.end(), has)) requests.emplace_back(c, -1);
  }
  for (const auto& [c, face] : requests) keep[static_cast<size_t>(c)] = 1;
  for (const auto& [a, b] : adjacent_cluster_pairs(topology_, clustering_.labels)) {
    for (const auto& request : requests) {
      if (request.first == a) keep[static_cast<size_t>(b)] = 1;
      if (request.first == b) keep[static_cast<size_t>(a)] = 1;
    }
  }
  // Splits first (the new clusters take the next ids), then as many merges, so n stays.
  int splits = 0;
  for (const auto& [c, face] : requests) {
    const int seed = clustering_.seeds[static_cast<size_t>(c)];
    const int added = face < 0 ? split_cluster(metric_, topology_, clustering_, c)
                               : split_cluster_at(metric_, topology_, clustering_, c, seed, face);
    if (added < 0) continue;
    ++splits;
    settled_[static_cast<size_t>(c)] = 0;
  }
  if (splits == 0) return nullptr;
  keep.resize(static_cast<size_t>(clustering_.num_clusters()), 1);
  settled_.resize(keep.size(), 0);
  settled_planes_.resize(keep.size());
  // A merge that leaves more clusters that are not disks (a neighbour touching both halves
  // of the pair now meets it twice) is undone, and the pair kept out.
  const auto not_disks = [&] {
    const PanelGraph graph = build_panel_graph(mesh_, topology_, clustering_.labels, clustering_.num_clusters());
    return std::count_if(graph.problems.begin(), graph.problems.end(), [](unsigned p) { return p != 0; });
  };
  const auto problems = not_disks();
  int merges = 0;
  for (int tries = 0; merges < splits && tries < kMergeTries; ++tries) {
    const auto [a, b] = cheapest_free_merge(metric_, topology_, clustering_, keep);
    if (a < 0) break;
    const size_t ai = static_cast<size_t>(a), bi = static_cast<size_t>(b);
    const Clustering unmerged = clustering_;
    merge_clusters(metric_, clustering_, a, b);
    if (not_disks() > problems) {
      clustering_ = unmerged;
      keep[ai] = keep[bi] = 1;
      continue;
    }
    ++merges;
    keep[ai] = 1;  // merged once at most
    settled_[ai] = 0;
    keep.erase(keep.begin() + static_cast<std::ptrdiff_t>(bi));
    settled_.erase(settled_.begin() + static_cast<std::ptrdiff_t>(bi));
    settled_planes_.erase(settled_planes_.begin() + static_cast<std::ptrdiff_t>(bi));
  }
  if (merges < splits) {  // no n clusters: leave the best as it is
    clustering_ = best_->clustering();
    return nullptr;
  }
  return make_attempt();
}

}  // namespace ff
