#include "core/remesher.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "core/cluster/cluster_edits.h"
#include "core/cluster/flood.h"
#include "core/cluster/lloyd.h"
#include "core/cluster/teleport.h"
#include "core/density/density_field.h"
#include "core/panels/boundary_term.h"
#include "core/panels/glass_split.h"
#include "core/panels/panel_check.h"
#include "core/panels/plane_fit.h"
#include "core/panels/split_requests.h"
#include "core/quality/report.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::Seeding:
      return "seeding";
    case Stage::Lloyd:
      return "lloyd";
    case Stage::Panels:
      return "panels";
    case Stage::Optimize:
      return "optimize";
    case Stage::Done:
      return "done";
  }
  return "unknown";
}

namespace {
// Panel rounds without a new fewest-invalid count before the panel phase gives up (k2 bounds
// it). The count jumps about from round to round, and progress comes late: on cow.off the
// fewest went 7 -> 6 after 45 rounds at 61 panels (valid at round 65) and 4 -> 3 after 36 at
// 78 (valid at round 96).
constexpr int kPanelPatience = 50;
// Split requests carried out per panel round, at most: each split merges a pair elsewhere and
// refloods both places, so many at once unsettle more panels than they fix (cow.off at 46-78
// panels asks 5-16 per round and its invalid count jumps around 20-40 for 100 rounds; with 3
// it goes down). Which 3 rotates with the round, so no request is dropped every round.
constexpr size_t kMaxSplitsPerRound = 3;
// A round with this many invalid panels or fewer gets the end's mend at once
// (PanelAttempt::mend_to_valid), kept only when every panel ends valid. The count falls to a
// few within 2-4 rounds and then often waits many rounds for the last one or two (bunny.off
// at 200 panels: 62, 9, 6, 3, 2, 3, 2, 2, 2, 0), which the mend fixes as often as not. A mend
// that fails leaves the round exactly as it was, so a run it cannot help goes on unchanged.
// bench/sweep_validity.sh at seed 1: 65 of 65 either way, panel rounds 952 -> 695, Hausdorff
// ratio geometric mean 1.000 (0.81-1.18). Up to 3, not 6: over the sweep at seeds 1-3 it
// succeeded 36% of its tries at 1 invalid panel, 12% at 2, 21% at 3, but only 5-9% at 4-6,
// where a try costs 3-4 ms on the bunny (a round about 4): there it pays only where a success
// saves rounds worth more than ten tries, and a failed try changes nothing. Seeds 1-6 and
// 31-36 against 6 (768 runs): valid 762 either way, panel rounds 9154 -> 9623, panel phase
// 87.7 -> 79.7 s (every mesh 0-29% less; bunny 200 1.41 -> 1.25 s), Hausdorff geometric
// mean 0.996.
constexpr int kMendEarlyAt = 3;
// An invalid cluster with fewer faces than the mean cluster's over this cannot be split near
// its problem (a split needs a face at the problem corner other than the seed): when the
// rounds stall with no split to make, it moves elsewhere instead, as an enclosed one does.
// On epcot.off (seeds 3, 4, 6 at 21-34 panels) a one-face cluster made a flipped triangle
// for 50 rounds; now valid within 7. Only when no split is asked: relocating tiny clusters
// at every stall reshuffled cow.off's chaotic runs (at seeds 1-6, 379 -> 377 valid).
constexpr int kTinyClusterShare = 20;
// Panel rounds after the first valid attempt with collapsed panels (coverage_round), at most.
constexpr int kCoverageRounds = 8;
// A corner below this (degrees) in a finished valid result starts the needle rounds
// (start_needle_rounds), which last this many panel rounds at most.
constexpr double kNeedleRoundsDeg = 1.0;
constexpr int kNeedleRounds = 16;
// "3 handles", "1 boundary loop".
std::string count_of(int count, const std::string& thing) {
  return std::to_string(count) + " " + thing + (count == 1 ? "" : "s");
}

// What makes a part need more panels than a sphere or a disc: " with 4 boundary loops and 3
// handles", or "".
std::string shape_traits(const PartShape& shape) {
  std::vector<std::string> traits;
  if (!shape.closed && shape.boundary_loops > 1) traits.push_back(count_of(shape.boundary_loops, "boundary loop"));
  if (shape.handles() > 0) traits.push_back(count_of(shape.handles(), "handle"));
  if (traits.empty()) return "";
  return " with " + traits[0] + (traits.size() > 1 ? " and " + traits[1] : "");
}

// The fewest panels a valid result can have (fewest_panels(), topology.h): fewer is refused at
// once rather than solved nine times (retries) into panels that must stay invalid (3holes.off
// opened by a hole at 2 panels: 8 s; the hyperboloid, an annulus, at 2: 16 s).
void check_enough_panels(const MeshTopology& topology, int panels) {
  const std::vector<PartShape> shapes = part_shapes(topology);
  std::vector<int> per_part;
  for (const PartShape& shape : shapes) per_part.push_back(fewest_panels(shape));
  const int fewest = std::accumulate(per_part.begin(), per_part.end(), 0);
  if (panels >= fewest) return;
  const std::string asked = "; asked for " + std::to_string(panels);
  if (shapes.size() == 1) {
    const PartShape& shape = shapes[0];
    const std::string why = shape.closed ? "each meets at least three others" : "each a disc";
    const std::string neighbours = shape_traits(shape).empty() ? "" : ", each neighbour along one side";
    throw InputError(std::string(shape.closed ? "a closed" : "an open") + " surface" + shape_traits(shape) +
                     " needs at least " + std::to_string(fewest) + " planar panels (" + why + neighbours + ")" + asked);
  }
  // Parts of one kind together, closed ones first: "1 closed part (at least 4 panels each)
  // and 2 open parts with 2 boundary loops (at least 3 each)".
  struct Group {
    bool open;
    std::string traits;
    int floor;  // the same for every part of the group: fewest_panels() reads only the shape
    int count;
  };
  std::vector<Group> groups;
  for (size_t c = 0; c < shapes.size(); ++c) {
    const bool open = !shapes[c].closed;
    const std::string traits = shape_traits(shapes[c]);
    const auto same = [&](const Group& g) { return g.open == open && g.traits == traits; };
    const auto found = std::find_if(groups.begin(), groups.end(), same);
    if (found != groups.end())
      ++found->count;
    else
      groups.push_back({open, traits, per_part[c], 1});
  }
  std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) { return !a.open && b.open; });
  std::string list;
  for (size_t k = 0; k < groups.size(); ++k) {
    const Group& g = groups[k];
    list += k == 0 ? "" : (k + 1 == groups.size() ? " and " : ", ");
    list += std::to_string(g.count) + (g.open ? " open" : " closed") + (g.count == 1 ? " part" : " parts") + g.traits +
            " (at least " + std::to_string(g.floor) + (k == 0 ? " panels each)" : " each)");
  }
  throw InputError("the mesh has " + list + ": it needs at least " + std::to_string(fewest) + " panels" + asked);
}

}  // namespace

Remesher::Remesher(TriMesh mesh, RemeshParams params)
    : mesh_(std::move(mesh)),
      topology_(build_topology(mesh_)),
      params_(std::move(params)),
      faces_(make_shaped_face_data(mesh_, topology_, params_.density, params_.density_expression, params_.anisotropy)),
      metric_(faces_, params_.weights, std::max(1, params_.panels)) {
  validate(params_);
  local_positions_.reserve(mesh_.positions.size());
  for (const Vec3& p : mesh_.positions) local_positions_.push_back((p - faces_.origin) / faces_.scale);
  // The panel checks' length tolerance: the quality report's (a length of tolerance * bbox
  // diagonal counts as zero), twice over, so a panel the rounds call valid passes the report's
  // independent check too. With a fixed 1e-9 in the local frame (scaled to the half extent) it
  // was 2-3.5 times smaller than the report's: on fandisk.off at 206 panels, seed 31, the
  // rounds ended "valid" on a needle triangle 1e-8 wide that the report then found without a
  // kernel, so the run ended invalid with no retry.
  check_tolerance_ = 2.0 * QualityOptions{}.tolerance * bbox_diagonal(mesh_) / faces_.scale;
  progress_ = Progress{Stage::Seeding, 0, 1, 0.0, 0};
}

void Remesher::validate(const RemeshParams& p) const {
  if (p.panels < 1) throw InputError("the number of panels must be at least 1");
  if (p.lloyd_iterations < 0 || p.lloyd_iterations > RemeshParams::kMaxIterations)
    throw InputError("iterations must be between 0 and " + std::to_string(RemeshParams::kMaxIterations));
  if (p.teleport_interval < 0 || p.teleport_moves < 0) throw InputError("teleport interval and moves must be >= 0");
  if (p.panel_rounds < 0 || p.panel_rounds > RemeshParams::kMaxIterations)
    throw InputError("panel rounds must be between 0 and " + std::to_string(RemeshParams::kMaxIterations));
  if (p.retries < 0 || p.retries > RemeshParams::kMaxRetries)
    throw InputError("retries must be between 0 and " + std::to_string(RemeshParams::kMaxRetries));
  if (!(p.min_corner_angle_deg >= 0.0 && p.min_corner_angle_deg <= 60.0))
    throw InputError("the minimum corner angle must be between 0 and 60 degrees");
  if (!(p.coplanar_angle_deg >= 0.0 && p.coplanar_angle_deg <= 10.0))
    throw InputError("the coplanar angle must be between 0 and 10 degrees");
  if (p.make_panels) check_enough_panels(topology_, p.panels);
  seeds_per_component(faces_, topology_, p.panels);  // throws on too many / too few panels
  validate_edits(p.edits);
  if (!p.make_panels && !p.edits.empty()) throw InputError("edits need panels (the panel phase is off)");
}

void Remesher::start_lloyd() {
  lloyd_done_ = 0;
  converged_ = false;
  best_.reset();
  polish_ = PolishState{};
  coverage_ = CoverageState{};
  needles_ = NeedleState{};
  settled_.clear();
  settled_planes_.clear();
  panel_rounds_done_ = 0;
  stalled_rounds_ = 0;
  best_round_ = 0;
  progress_ = Progress{Stage::Lloyd, 0, params_.lloyd_iterations, clustering_.energy * faces_.area_to_world(), 0};
  if (params_.lloyd_iterations == 0) after_lloyd();
}

void Remesher::after_lloyd() {
  // moments_ holds the last Lloyd refit's moments: the first panel round starts from them.
  if (!params_.make_panels) {
    progress_.stage = Stage::Done;
    return;
  }
  progress_ = Progress{Stage::Panels, 0, std::max(1, params_.panel_rounds), progress_.energy, 0};
}

namespace {

// A Lloyd iteration of the panel phase: the clustering metric plus the boundary term.
// Most clusters keep their faces here (the settled ones): `moments` sums only the others.
void panel_lloyd_iteration(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                           const ExtraCost* extra, ClusterMomentsCache& moments) {
  moments.choose_seeds(metric, clustering);
  flood(metric, topology, clustering, extra, /*with_energy=*/false);
  moments.refit(metric, clustering);
  for (int& s : clustering.sticky) {
    if (s > 0) --s;
  }
}

}  // namespace

std::unique_ptr<PanelAttempt> Remesher::make_attempt() {
  PanelAttemptOptions options;
  options.layout.diameter = metric_.diameter();
  options.layout.tolerance = check_tolerance_;
  options.layout.min_corner_angle_deg = min_corner_angle();
  options.layout.glass = params_.glass;
  options.master_angle_deg = params_.coplanar_angle_deg;
  options.fixed = settled_;
  options.fixed_planes = settled_planes_;
  hold(options.fixed, options.fixed_planes);  // locked panels and their neighbours
  options.layout.held_nodes = held_nodes();
  options.layout.held_single = held_single();
  options.layout.held_grouping = held_grouping();
  options.hinge_of = hinges();
  locked_limits(options.layout.locked_spike_distance, options.layout.locked_diameter);
  const std::vector<ClusterMoments>& moments = moments_.update(faces_, clustering_.labels, clustering_.num_clusters());
  // Between rounds only some faces move: the graph is updated around them (the same graph).
  const PanelGraph& graph =
      update_panel_graph(mesh_, topology_, clustering_.labels, clustering_.num_clusters(), graph_state_);
  return std::make_unique<PanelAttempt>(mesh_, topology_, local_positions_, faces_, clustering_, options, &moments,
                                        &graph);
}

void Remesher::panel_round() {
  if (!best_) {  // a new panel phase
    alternates_.clear();
    failed_mend_.clear();
  }
  std::unique_ptr<PanelAttempt> attempt = make_attempt();
  int invalid = attempt->num_invalid();
  if (invalid == 0) {
    // Judged as the end judges it (orientation included): a misoriented panel found only
    // after the rounds is one they never worked on (epcot.off at 27 panels, seed 6).
    attempt->layout().judge_orientation();
    invalid = attempt->num_invalid();
  }
  std::vector<int> invalid_clusters;
  if (invalid > 0 && invalid <= kMendEarlyAt) {
    for (size_t c = 0; c < attempt->layout().issues().size(); ++c) {
      if (!attempt->layout().issues()[c].valid()) invalid_clusters.push_back(static_cast<int>(c));
    }
  }
  // Not again on the very panels it last failed on: the clustering around them has barely
  // moved since (see failed_mend_).
  if (!invalid_clusters.empty() && invalid_clusters != failed_mend_) {
    // The settled planes held, as in the rounds: the mend works around the invalid panels.
    std::vector<char> held = attempt->settled_clusters();
    const std::vector<char> locked = held_clusters();
    for (size_t c = 0; c < locked.size() && c < held.size(); ++c) held[c] = held[c] || locked[c];
    if (attempt->mend_to_valid(faces_, held, PanelAttemptOptions{}))
      invalid = 0;
    else
      failed_mend_ = invalid_clusters;
  }
  ++panel_rounds_done_;
  progress_.iteration = panel_rounds_done_;
  progress_.invalid_panels = invalid;
  if (invalid == 0 && coverage_round(attempt)) return;
  const bool improved = !best_ || invalid < best_->num_invalid();
  stalled_rounds_ = improved ? 0 : stalled_rounds_ + 1;
  if (improved) best_round_ = panel_rounds_done_;
  // k2 is the hard limit; before it, a run whose fewest invalid panels has not gone down for
  // kPanelPatience rounds stops: inputs that cannot get better end early.
  // After a valid fallback (coverage_round), also at most kCoverageRounds rounds from the first.
  const bool last = invalid == 0 || panel_rounds_done_ >= std::max(1, params_.panel_rounds) ||
                    panel_rounds_done_ - best_round_ >= kPanelPatience ||
                    (coverage_.fallback && panel_rounds_done_ - coverage_.first_round >= kCoverageRounds) ||
                    (needles_.fallback && panel_rounds_done_ - needles_.first_round >= kNeedleRounds);
  if (last) {
    if (!best_ || invalid <= best_->num_invalid()) std::swap(best_, attempt);
    keep_alternate(std::move(attempt));
    if (best_->num_invalid() > 0 && coverage_.fallback)  // valid, with collapsed panels
      finish_with_fallback();
    else if (best_->num_invalid() > 0 && needles_.fallback)  // valid, with a needle corner
      finish_with_needle_fallback();
    else
      finish_panels();
    return;
  }
  fix_panels(*attempt);
  if (improved) std::swap(best_, attempt);
  keep_alternate(std::move(attempt));
}

// A valid attempt (judged as the end judges it) whose panels include collapsed ones: the
// paper's checks pass it, but a collapsed panel is a sliver over its neighbours' faces (no
// part to cut), so while the coverage rounds last its collapsed clusters move elsewhere and
// the rounds go on; it is kept as the fallback when it has the fewest collapsed panels so
// far. The last coverage round ends the run with the fallback. False (an ordinary round's
// end) when nothing collapsed, with locked panels (their clusters stay where they are) or
// after the designer's edits (a cluster they split off stays where they asked for it).
bool Remesher::coverage_round(std::unique_ptr<PanelAttempt>& attempt) {
  const int collapsed = attempt->layout().faults().collapsed;
  if (collapsed == 0 || !locks_.empty() || next_edit_ > 0) return false;
  // The finish fits the planes to the surface, which often widens a collapsed panel (never
  // narrows one: try_planes): judged as the end will judge it, such an attempt needs no
  // more rounds (fandisk.off at 300 panels, seed 7: 8 rounds that ended where they began).
  // When the fit leaves a collapsed panel, the rounds go on from the attempt as it was.
  if (params_.optimize_planes) {
    PanelAttempt::Saved unfitted = attempt->save();
    fit_planes(*attempt);
    if (attempt->layout().faults().collapsed == 0) return false;
    attempt->restore(std::move(unfitted));
  }
  if (!coverage_.fallback) coverage_.first_round = panel_rounds_done_;
  const bool fewer = !coverage_.fallback || collapsed < coverage_.fallback->layout().faults().collapsed;
  const bool more = panel_rounds_done_ < std::max(1, params_.panel_rounds) &&
                    panel_rounds_done_ - coverage_.first_round < kCoverageRounds;
  if (more) fix_panels(*attempt, /*coverage=*/true);
  if (fewer) coverage_.fallback = std::move(attempt);
  if (more) return true;
  finish_with_fallback();
  return true;
}

void Remesher::finish_with_fallback() {
  // In the needle rounds: the needle's fallback has no collapsed panel, so it is the better.
  if (needles_.fallback) {
    finish_with_needle_fallback();
    return;
  }
  best_ = std::move(coverage_.fallback);
  alternates_.clear();
  finish_panels();
}

// Attempts that did not become the best but came close, for mend_best(): the last fixes
// mend one clustering where they fail on a slightly different one (on 3holes.off at 102
// panels they fail on the best round and succeed on the three after it). The fewest invalid
// first, the later round first among equals; only those within kAlternateMargin invalid
// panels of the best (a whole attempt is large, and one far behind is not close). Not with
// locked panels (their held clusters are numbered in the clustering of the moment).
void Remesher::keep_alternate(std::unique_ptr<PanelAttempt> attempt) {
  constexpr size_t kAlternates = 4;
  constexpr int kAlternateMargin = 2;
  if (!attempt || attempt->num_invalid() == 0 || !locks_.empty()) return;
  // The best only gets better, so one too far behind now stays so: drop them (the last).
  const int limit = best_ ? best_->num_invalid() + kAlternateMargin : std::numeric_limits<int>::max();
  while (!alternates_.empty() && alternates_.back()->num_invalid() > limit) alternates_.pop_back();
  const int invalid = attempt->num_invalid();
  if (invalid > limit) return;
  // Kept in order: before the first with as many invalid panels or more.
  const auto at = std::find_if(alternates_.begin(), alternates_.end(),
                               [invalid](const auto& a) { return a->num_invalid() >= invalid; });
  if (at - alternates_.begin() >= static_cast<std::ptrdiff_t>(kAlternates)) return;
  alternates_.insert(at, std::move(attempt));
  if (alternates_.size() > kAlternates) alternates_.pop_back();
}

void Remesher::fix_panels(const PanelAttempt& attempt, bool coverage) {
  // Settled clusters (valid among valid) keep their faces and planes from now on, so each
  // round works where panels are still invalid and does not undo progress elsewhere.
  settled_ = attempt.settled_clusters(coverage);
  settled_planes_ = attempt.cluster_planes();
  hold(settled_, settled_planes_);
  const std::vector<char> held = held_clusters();
  const auto is_held = [&](int c) { return !held.empty() && held[static_cast<size_t>(c)]; };
  // Clusters that are not disks are cut at once; enclosed ones, and those too small to cut,
  // move elsewhere. Invalid panels get a split near their problem (merging elsewhere to keep
  // n) only when the rounds stall: a split refloods its neighbourhood, while the boundary term
  // alone converges steadily as long as it makes progress.
  // When the invalid panels stop going away, split near one of them (up to three of them from
  // 200 panels on: stall_splits()).
  const bool stalled = stalled_rounds_ >= 3;
  if (stalled) stalled_rounds_ = 0;
  // Acute corners do not move with the boundary term (it shifts faces, not where clusters
  // meet), so with a minimum angle a stall splits at up to three of them at once.
  int splits = stalled ? (min_corner_angle() > 0.0 ? 3 : stall_splits(clustering_.num_clusters())) : 0;
  const ClusterCuts cuts = cluster_cuts(mesh_, topology_, attempt);
  if (splits > 1 && min_corner_angle() <= 0.0) {
    // The stall's extra splits give way to the cuts of clusters that are not disks (asked
    // first, every round), so that the cap below never rotates away the split near the
    // largest invalid panel, which one split per stall always made.
    splits = std::max(1, std::min(splits, static_cast<int>(kMaxSplitsPerRound) - static_cast<int>(cuts.cuts.size())));
  }
  std::vector<std::pair<int, int>> requests = split_requests(mesh_, topology_, attempt, cuts.cuts, splits, held);
  requests.erase(std::remove_if(requests.begin(), requests.end(), [&](const auto& r) { return is_held(r.first); }),
                 requests.end());
  if (requests.size() > kMaxSplitsPerRound) {
    const size_t first = static_cast<size_t>(panel_rounds_done_) % requests.size();
    std::rotate(requests.begin(), requests.begin() + static_cast<std::ptrdiff_t>(first), requests.end());
    requests.resize(kMaxSplitsPerRound);
  }
  // Merges happen away from the splits; a settled pair may merge (then it is unsettled below).
  const std::vector<int> seeds_before = clustering_.seeds;
  const std::vector<Proxy> proxies_before = clustering_.proxies;
  if (!requests.empty()) {
    std::vector<char> protect = held;
    protect.resize(settled_.size(), 0);
    std::vector<char> requested(settled_.size(), 0);
    for (const auto& request : requests) requested[static_cast<size_t>(request.first)] = 1;
    for (const auto& [a, b] : adjacent_cluster_pairs(topology_, clustering_.labels)) {
      if (requested[static_cast<size_t>(a)]) protect[static_cast<size_t>(b)] = 1;
      if (requested[static_cast<size_t>(b)]) protect[static_cast<size_t>(a)] = 1;
    }
    split_near(metric_, topology_, clustering_, requests, protect, 3, /*reflood_after=*/false);
  }
  // Clusters that cannot be panels where they are move elsewhere: enclosed ones, and those
  // that are not disks and have no face to cut them at but their seed.
  std::vector<int> enclosed = enclosed_clusters(attempt);
  enclosed.insert(enclosed.end(), cuts.uncuttable.begin(), cuts.uncuttable.end());
  if (coverage) {  // collapsed clusters: their faces are under their neighbours' panels already
    for (size_t c = 0; c < attempt.layout().issues().size(); ++c)
      if (attempt.layout().issues()[c].collapsed) enclosed.push_back(static_cast<int>(c));
  }
  if (stalled && requests.empty()) {  // a stall with no split to make: tiny clusters move
    const std::vector<int> tiny = tiny_invalid_clusters(attempt, kTinyClusterShare);
    enclosed.insert(enclosed.end(), tiny.begin(), tiny.end());
  }
  enclosed.erase(std::remove_if(enclosed.begin(), enclosed.end(), is_held), enclosed.end());
  relocate_clusters(metric_, topology_, clustering_, enclosed, settled_);
  settled_.resize(static_cast<size_t>(clustering_.num_clusters()), 0);
  settled_planes_.resize(settled_.size());
  // Then a Lloyd iteration with the boundary term of this attempt's panels; clusters the
  // splits moved have no panel of their own yet.
  BoundaryTerm term(faces_, attempt.layout(), params_.weights.boundary, metric_.diameter());
  for (size_t c = 0; c < settled_.size(); ++c) {
    const bool moved = c >= proxies_before.size() || seeds_before[c] != clustering_.seeds[c] ||
                       proxies_before[c].center != clustering_.proxies[c].center ||
                       proxies_before[c].normal != clustering_.proxies[c].normal;
    if (!moved) continue;
    settled_[c] = 0;
    term.ignore(static_cast<int>(c));
  }
  if (held.empty()) {
    term.freeze(settled_, clustering_.labels);
    panel_lloyd_iteration(metric_, topology_, clustering_, &term, moments_);
  } else {
    // Held clusters keep their faces; a locked panel's neighbours are not frozen beyond
    // that: free faces may join them where the boundary term says so (as in the Lloyd
    // steps), which gives the clusters beyond them room to settle.
    std::vector<char> frozen = settled_;
    for (size_t c = 0; c < held.size() && c < frozen.size(); ++c) frozen[c] = frozen[c] && !held[c];
    for (int c : locked_clusters()) frozen[static_cast<size_t>(c)] = 1;
    term.freeze(frozen, clustering_.labels);
    const std::vector<int> held_faces = held_labels();
    const WithHeldFaces with_held(term, held_faces);
    panel_lloyd_iteration(metric_, topology_, clustering_, &with_held, moments_);
  }
  progress_.energy = clustering_.energy * faces_.area_to_world();
}

void Remesher::finish_panels() {
  clustering_ = best_->clustering();    // before mend_best: held_clusters() reads it
  best_->layout().judge_orientation();  // what the quality report judges (issue 3)
  if (best_->num_invalid() > 0) mend_best();
  // Still invalid: the polish (remesher_polish.cpp) tries more, one attempt per step.
  if (best_->num_invalid() > 0 && start_polish()) {
    progress_.invalid_panels = best_->num_invalid();
    return;
  }
  end_panels();
}

std::uint64_t Remesher::solve_seed() const {
  if (retries_done_ == 0) return params_.seed;
  SplitMix64 mix(params_.seed);  // retry k: the k-th number of the seed's own sequence
  std::uint64_t seed = 0;
  for (int k = 0; k < retries_done_; ++k) seed = mix.next();
  return seed;
}

bool Remesher::retry_if_invalid() {
  EarlierSolve& e = earlier_;
  if (e.best && e.best->num_invalid() <= best_->num_invalid()) {  // the earlier is as good: back to it
    std::swap(best_, e.best);
    std::swap(lloyd_done_, e.lloyd_done);
    std::swap(teleports_, e.teleports);
    std::swap(panel_rounds_done_, e.panel_rounds);
    std::swap(converged_, e.converged);
    clustering_ = best_->clustering();
  }
  // Only a solve a new seeding can stand in for: no locked panels, no edits made part of the
  // design by a later parameter change, the count of the parameters.
  const bool plain = locks_.empty() && base_edits_ == 0 && clustering_.num_clusters() == params_.panels;
  if (best_->num_invalid() == 0 || retries_done_ >= params_.retries || !plain) {
    earlier_ = EarlierSolve{};
    return false;
  }
  earlier_ = EarlierSolve{std::move(best_), lloyd_done_, teleports_, panel_rounds_done_, converged_};
  ++retries_done_;
  alternates_.clear();
  start_over();  // from the retry's seed (solve_seed)
  return true;
}

void Remesher::start_over() {
  clustering_ = Clustering{};
  teleports_ = 0;
  lloyd_done_ = 0;
  converged_ = false;
  progress_ = Progress{Stage::Seeding, 0, 1, 0.0, 0};
}

void Remesher::end_panels() {
  if (retry_if_invalid()) return;
  progress_.energy = clustering_.energy * faces_.area_to_world();
  panels_ = best_->layout().to_panel_mesh(faces_);
  progress_.invalid_panels = panels_.num_invalid();
  // Valid panels always go on: the needle widening runs even without the plane fit.
  const bool optimize = panels_.num_invalid() == 0;
  progress_.stage = optimize ? Stage::Optimize : Stage::Done;
  if (optimize) progress_ = Progress{Stage::Optimize, 0, 1, progress_.energy, 0};
  if (!optimize) record_planes(), cut_glass();
}

// The panel rounds are over and some panels are still invalid: the last fixes, on the best
// attempt only (runs that end valid never get here, so they are unchanged). Locked panels
// and their neighbours keep their planes. Where a runner-up takes the best's place,
// clustering_ becomes its clustering.
void Remesher::mend_best() {
  best_->mend(faces_, held_clusters(), PanelAttemptOptions{});
  // Then the close runners-up (keep_alternate), until one ends valid; one replaces the
  // best only with fewer invalid panels, so a run the best's mend leaves as it was stays so.
  bool replaced = false;
  for (std::unique_ptr<PanelAttempt>& alternate : alternates_) {
    if (best_->num_invalid() == 0) break;
    alternate->layout().judge_orientation();
    alternate->mend(faces_, {}, PanelAttemptOptions{});
    if (alternate->num_invalid() < best_->num_invalid()) std::swap(best_, alternate), replaced = true;
  }
  alternates_.clear();
  if (replaced) clustering_ = best_->clustering();
}

void Remesher::cut_glass() {
  if (!params_.glass) return;
  split_concave_panels(panels_, mesh_, params_.min_corner_angle_deg);
  progress_.invalid_panels = panels_.num_invalid();
}

// Beyond the paper: the planes fitted to the surface (least squares of its distance to the
// panels, surface_fit_planes), each kept only where the panels stay valid and none collapses.
// Once per attempt: the coverage rounds may have fitted it already (coverage_round).
void Remesher::fit_planes(PanelAttempt& attempt) {
  if (!params_.optimize_planes || attempt.planes_fitted()) return;
  attempt.set_planes_fitted();
  PanelLayout& layout = attempt.layout();
  const std::vector<int>& labels = attempt.clustering().labels;
  std::vector<Plane> fitted = surface_fit_planes(
      faces_, labels, layout.planes(), layout.node_constraints(),
      border_moments(topology_, local_positions_, labels, attempt.clustering().num_clusters()), kBorderFitWeight);
  // Locked panels and their neighbours keep their planes.
  const std::vector<char> held = held_clusters();
  for (size_t c = 0; c < held.size(); ++c) {
    const int master = layout.planes().master_of[c];
    if (held[c]) fitted[static_cast<size_t>(master)] = layout.planes().planes[static_cast<size_t>(master)];
  }
  // The fitted planes move together, but try_planes takes them one at a time, each only
  // where the panels stay valid: a plane refused while its neighbours were still where they
  // were may pass once they moved (a second pass), or part of the way (half, then a quarter).
  layout.try_planes(fitted, 2);
  for (double step : {0.5, 0.25}) layout.try_planes(planes_toward(layout.planes().planes, fitted, step));
}

void Remesher::optimize_planes() {
  fit_planes(*best_);
  PanelLayout& layout = best_->layout();
  // Then the needles (corners below kNeedleCornerDeg) the fit leaves at split nodes: another
  // pairing, or the group as one point (which moves planes: not those of locked panels and
  // their neighbours).
  layout.widen_needle_corners(kNeedleCornerDeg, held_clusters());
  // Last: it pins planes to points, which the fit above would undo.
  if (params_.single_point_nodes) layout.make_single_point_nodes(held_clusters());
  if (start_needle_rounds()) return;
  finish_layout();
}

void Remesher::finish_layout() {
  panels_ = best_->layout().to_panel_mesh(faces_);
  progress_.iteration = 1;
  progress_.invalid_panels = panels_.num_invalid();
  progress_.stage = Stage::Done;
  record_planes();
  cut_glass();
}

double Remesher::min_corner_angle() const {
  return needles_.fallback ? kNeedleRoundsDeg : params_.min_corner_angle_deg;
}

// A finished valid result with a corner below kNeedleRoundsDeg: a needle no fabricator can
// cut, which the paper's checks pass and the finish's widening (widen_needle_corners) did not
// remove (mostly at nodes of three planes, where no pairing moves it). When the designer set
// no minimum corner angle, the result is kept as it is as the fallback and up to
// kNeedleRounds more panel rounds judge such corners as panel problems (as --min-angle does
// in every round, at a cost in every solve); a valid attempt then is finished as usual, or
// the fallback ends the run. Not with locked panels or edits (their clusters stay as they
// are), nor once the rounds' budget is spent.
bool Remesher::start_needle_rounds() {
  if (needles_.tried || params_.min_corner_angle_deg > 0.0 || !locks_.empty() || next_edit_ > 0 || base_edits_ > 0)
    return false;
  if (panel_rounds_done_ >= std::max(1, params_.panel_rounds)) return false;
  PanelLayout& layout = best_->layout();
  if (!(layout.smallest_corner_deg() < kNeedleRoundsDeg)) return false;
  needles_.tried = true;
  needles_.first_round = panel_rounds_done_;
  // The next rounds work on the needles: judged as problems for fix_panels, then put back.
  layout.judge_min_corner_angle(kNeedleRoundsDeg);
  stalled_rounds_ = 0;
  fix_panels(*best_);
  layout.judge_min_corner_angle(0.0);
  needles_.fallback = std::move(best_);  // best_ empty: the rounds start a new best
  progress_ = Progress{Stage::Panels, panel_rounds_done_, std::max(1, params_.panel_rounds), progress_.energy, 0};
  return true;
}

void Remesher::finish_with_needle_fallback() {
  best_ = std::move(needles_.fallback);
  alternates_.clear();
  clustering_ = best_->clustering();
  progress_.energy = clustering_.energy * faces_.area_to_world();
  finish_layout();
}

Progress Remesher::step() {
  switch (progress_.stage) {
    case Stage::Seeding: {
      const std::vector<int> seeds =
          place_seeds(faces_, topology_, params_.panels, params_.seeding, solve_seed(), params_.weights.density);
      clustering_ = initial_clustering(metric_, topology_, seeds);
      start_lloyd();
      break;
    }
    case Stage::Lloyd: {
      if (!locks_.empty()) {  // held clusters keep their faces; no teleports
        lloyd_step_held();
        break;
      }
      const int it = lloyd_done_ + 1;
      int moves = 0;
      // Teleport early and mid-phase, never in the last iterations, so Lloyd settles after.
      if (params_.teleport_interval > 0 && it % params_.teleport_interval == 0 && it + 2 <= params_.lloyd_iterations) {
        TeleportOptions options;
        options.max_moves = params_.teleport_moves > 0 ? params_.teleport_moves : std::max(1, params_.panels / 64);
        moves = teleport(metric_, topology_, clustering_, options, &moments_);
        teleports_ += moves;
      }
      // A teleport refloods and refits, which is this iteration's work; otherwise one Lloyd step.
      if (moves == 0) {
        const LloydResult r = lloyd_iteration(metric_, topology_, clustering_, &moments_);
        if (r.changed_faces == 0) converged_ = true;
      }
      lloyd_done_ = it;
      progress_.iteration = it;
      progress_.energy = clustering_.energy * faces_.area_to_world();
      if (converged_ || it >= params_.lloyd_iterations) after_lloyd();
      break;
    }
    case Stage::Panels:
      if (polish_.active)
        polish_step();
      else
        panel_round();
      break;
    case Stage::Optimize:
      optimize_planes();
      break;
    case Stage::Done:
      apply_pending_edits();
      break;
  }
  // Derived, not kept: panel rounds while a valid result waits as the needles' fallback.
  progress_.needle_rounds = progress_.stage == Stage::Panels && needles_.fallback != nullptr;
  return progress_;
}

Progress Remesher::run() {
  while (!done()) step();
  return progress_;
}

EnergyTerms Remesher::energy() const {
  if (clustering_.labels.empty()) return {};
  return clustering_energy(metric_, cluster_moments(faces_, clustering_.labels, clustering_.num_clusters()),
                           clustering_.proxies)
      .scaled(faces_.area_to_world());
}

void Remesher::set_params(RemeshParams params) {
  // Build and check everything first: bad parameters throw and leave the Remesher, and the
  // designer's last good result, exactly as they were.
  validate(params);
  // New face data only for a new density field (it is the largest thing a Remesher holds).
  std::optional<FaceData> faces;
  if (params.density != params_.density || params.density_expression != params_.density_expression ||
      params.anisotropy != params_.anisotropy)
    faces = make_shaped_face_data(mesh_, topology_, params.density, params.density_expression, params.anisotropy);
  Metric(faces ? *faces : faces_, params.weights, params.panels);  // throws on bad weights
  // A changed edit list replays on a fresh solve (set_edits is the incremental way).
  const bool restart = clustering_.labels.empty() || params.seed != params_.seed || params.seeding != params_.seeding ||
                       !(params.edits == params_.edits);
  // After edits the clustering has its own count: the new one is reached from there, unless
  // the count asked for is no change (kept_count): then params().panels stays the target.
  const int old_panels = next_edit_ > 0 ? clustering_.num_clusters() : params_.panels;
  const bool keep_count = !restart && kept_count(params);
  if (keep_count) {
    params.panels = params_.panels;
    if (same_solve(params, params_)) return;  // nothing changed: no re-solve
  }
  const int target = keep_count ? old_panels : params.panels;
  if (!restart && !locks_.empty()) {
    // The fewest a count change can reach: the held clusters, and one for each part of the
    // surface they leave free.
    const std::vector<char> held = held_clusters();
    const int kept = static_cast<int>(std::count(held.begin(), held.end(), 1));
    const int free_parts = free_parts_with_locks();
    if (target < kept + free_parts)
      throw InputError(std::to_string(target) + " panels cannot keep the " + std::to_string(locks_.size()) +
                       (locks_.size() == 1 ? " locked panel" : " locked panels") +
                       ": with their neighbours they hold " + std::to_string(kept) +
                       " panels, and the rest of the surface needs at least " + std::to_string(free_parts) +
                       "; ask for at least " + std::to_string(kept + free_parts) + ", or unlock some");
  }
  params_ = std::move(params);
  earlier_ = EarlierSolve{};  // a new solve: its own retries
  retries_done_ = 0;
  if (faces) faces_ = std::move(*faces);
  moments_.clear();
  metric_ = Metric(faces_, params_.weights, params_.panels);
  if (restart) {
    clear_edits();
    start_over();
    return;
  }
  // The edits so far are part of the design now: undo replays from the next solve.
  base_edits_ = next_edit_;
  base_.reset();
  if (!locks_.empty()) {
    change_count_held(target);
    start_lloyd();
    return;
  }
  if (target > old_panels) add_clusters(metric_, topology_, clustering_, target - old_panels);
  if (target < old_panels) remove_clusters(metric_, topology_, clustering_, old_panels - target);
  if (target == old_panels) refit(metric_, clustering_);  // proxies and energy under the new metric
  start_lloyd();
}

}  // namespace ff
