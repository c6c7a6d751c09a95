#pragma once
// Remesher: the pipeline as a resumable state machine (DESIGN.md 2). step() does bounded
// work (seeding, or one Lloyd iteration) and returns Progress, so the CLI, the tests and the
// web worker drive the same object and can stop, report or change parameters between steps.
//
// Stages: Seeding -> Lloyd (k1 iterations, teleports every few) -> Panels (up to k2 rounds of
// corners -> intersect planes -> validate -> fix -> Lloyd with the boundary term) ->
// Optimize (the planes themselves, least squares, once the combinatorics settled) -> Done.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/face_data.h"
#include "core/cluster/metric.h"
#include "core/cluster/moments_cache.h"
#include "core/cluster/seeding.h"
#include "core/density/anisotropy.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_attempt.h"
#include "core/panels/panel_graph_update.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/plane.h"

namespace ff {

// A designer's edit of one panel (paper 6, future work), naming panels by a face inside them:
// face ids are stable for a mesh, cluster ids change between solves. Applied in order to the
// solved design (remesher_edits.cpp): split cuts the panel in two, merge joins it with the
// neighbouring panel containing `with`, lock holds it (its faces, plane and outline) through
// every later re-solve, unlock releases it.
struct PanelEdit {
  enum class Op { Split, Merge, Lock, Unlock };
  Op op = Op::Split;
  int face = 0;
  int with = -1;  // merge only
  bool operator==(const PanelEdit& o) const { return op == o.op && face == o.face && with == o.with; }
};
const char* edit_name(PanelEdit::Op op);

struct RemeshParams {
  // The largest lloyd_iterations and panel_rounds, and the largest retries (Remesher throws
  // above them; the CLI and the page's JSON parameters check the same).
  static constexpr int kMaxIterations = 100000;
  static constexpr int kMaxRetries = 10;
  // The count the solve targets. With edits the design has this many panels plus splits minus
  // merges (Remesher::num_panels()); set_params with the same edits and either this target or
  // that current count changes nothing about the count (Remesher::kept_count).
  int panels = 100;
  // 0 to kMaxSeed, 2^53 - 1: the largest a JSON number (the page, share links) holds exactly, so
  // every seed the CLI takes can be typed on the page and travel in a link.
  static constexpr std::int64_t kMaxSeed = (std::int64_t{1} << 53) - 1;
  std::uint64_t seed = 1;
  MetricWeights weights;
  // Empty (uniform), one value per mesh vertex or one per face; higher = smaller panels.
  std::vector<double> density;
  // Procedural density (density/expression.h), evaluated per vertex and multiplied with
  // `density` when both are given; empty = none.
  std::string density_expression;
  // Elongated panels along a direction (density/anisotropy.h); none by default.
  Anisotropy anisotropy;
  int lloyd_iterations = 20;  // k1: an upper bound; stops earlier at a fixed point
  SeedingMethod seeding = SeedingMethod::FarthestPoint;
  int teleport_interval = 4;  // teleport before every 4th iteration; 0 = never
  int teleport_moves = 0;     // moves per teleport; 0 = automatic (1 per 64 clusters, >= 1)
  bool make_panels = true;    // false: stop after the Lloyd phase (`flatfacet cluster`)
  // k2: an upper bound; stops at the first valid panel mesh, or after 50 rounds in which the
  // fewest invalid panels did not go down.
  int panel_rounds = 100;
  // Solves again from a new seeding, at most this many times, when the panels end invalid
  // (0: never): the panel phase is chaotic, and where one clustering leaves a panel or two
  // invalid, another of the same count often has none (cow.off at 46-78 panels). The result
  // with the fewest invalid panels is kept, the earlier on ties; a run valid at once never
  // retries, so it is unchanged. Each retry's seed is derived from `seed` (deterministic).
  // Not with locked panels, nor once a parameter change made edits part of the design; a
  // fresh solve that replays edits retries as the first solve did, before the edits.
  // 8: cow.off at 46 panels, seeds 1-144, ends valid 129 times with 4, 138 with 6, 142 with 8
  // and 143 with 10 (bench/README.md, "Retries 4 -> 8"); each retry costs a whole solve only
  // on a run that would otherwise end invalid, so a run that stays invalid takes 9 solves.
  int retries = 8;
  // Where four or more planes meet: false (default) splits the node into valence-3 nodes
  // joined by short edges; true makes all of them pass through one point (paper 2.2).
  bool single_point_nodes = false;
  bool optimize_planes = true;  // beyond the paper: fit the planes to the surface at the end
  // Glass mode (DESIGN.md 3): after the solve, concave panels are cut at their reflex corners
  // into coplanar convex pieces (glass_split.h).
  bool glass = false;
  // The designer's smallest corner angle in degrees (0 = off, at most 60): a panel corner
  // below it is a problem the panel rounds fix like the others; what remains is reported.
  double min_corner_angle_deg = 0.0;
  // Neighbouring clusters whose planes differ by less than this many degrees share one
  // master plane (paper 2.4: 1 degree; 0 = none, at most 10), unless their planes meet near
  // them, as neighbours on a smoothly curved surface do (master_planes.h).
  double coplanar_angle_deg = 1.0;
  // Per-panel edits, applied in order once the solve is done (PanelEdit; DESIGN.md 3).
  std::vector<PanelEdit> edits;
  // A new field must be compared in Remesher::same_solve too (remesher_edits.cpp).
};

enum class Stage { Seeding, Lloyd, Panels, Optimize, Done };
const char* stage_name(Stage stage);

struct Progress {
  Stage stage = Stage::Seeding;
  int iteration = 0;  // within the stage
  int of = 0;         // the stage's iteration limit
  double energy = 0.0;
  int invalid_panels = 0;
  // In the needle rounds (Remesher::start_needle_rounds): a valid result had a corner below
  // 1 degree, so the stage went back from Optimize to Panels on purpose.
  bool needle_rounds = false;
};

class Remesher {
 public:
  // The mesh must be clean (clean_mesh): edge-manifold and consistently oriented.
  // Throws InputError for bad parameters (panel count vs faces and components, weights,
  // density size or values, negative iteration counts).
  Remesher(TriMesh mesh, RemeshParams params);
  // The metric refers to the face data inside: not copyable or movable.
  Remesher(const Remesher&) = delete;
  Remesher& operator=(const Remesher&) = delete;

  Progress step();
  // Done: the solve finished and every edit of params().edits is applied.
  bool done() const { return progress_.stage == Stage::Done && next_edit_ >= params_.edits.size(); }
  // Steps until done; returns the final progress.
  Progress run();
  const Progress& progress() const { return progress_; }

  // New parameters, warm-started from the current clustering: a changed panel count splits
  // the worst or merges the cheapest clusters, changed weights or density refit the proxies;
  // then the Lloyd phase runs again. A changed seed or seeding method starts over (and the
  // clustering is empty until the next step()). Throws InputError for bad parameters and
  // then leaves everything as it was. Locked panels keep their faces and planes (set_edits).
  // After edits, a count that is no change (kept_count) keeps the target and the count now;
  // when nothing else changed either, nothing happens (no re-solve; undo still replays).
  void set_params(RemeshParams params);
  // Whether `params` leaves the panel count as it is: edits are applied, the edit list is the
  // same, and params.panels is the target (params().panels) or the count now (num_panels()),
  // so a page showing the count after a split can send either.
  bool kept_count(const RemeshParams& params) const;

  // The edit list (params().edits) changes: if it is the current list plus more edits, the
  // new ones are applied to the current design; otherwise the design from before the first
  // edit since the last parameter change is restored and the list replayed from there (undo,
  // redo); a list that differs before that point is replayed on a fresh solve. A changed
  // edit list in set_params also solves fresh, then replays. Runs to done before returning.
  // Throws InputError naming the edit (face out of range, merge of panels that are not
  // neighbours, split or merge of a locked panel, unlock of a panel not locked) and then
  // leaves everything as it was.
  void set_edits(std::vector<PanelEdit> edits);

  // The number of panels (clusters) now: params().panels plus splits minus merges.
  int num_panels() const { return clustering_.num_clusters(); }
  // The clusters locked by an edit, sorted (empty before panels).
  std::vector<int> locked_clusters() const;

  const TriMesh& mesh() const { return mesh_; }
  const MeshTopology& topology() const { return topology_; }
  const RemeshParams& params() const { return params_; }
  const Clustering& clustering() const { return clustering_; }
  const Metric& metric() const { return metric_; }
  // The panels of the last panel round (empty before the panel phase): the valid result when
  // there is one, else the round with the fewest invalid panels, its problems listed per panel.
  const PanelMesh& panels() const { return panels_; }
  int panel_rounds_done() const { return panel_rounds_done_; }
  // Energy of the current clustering by term, in world units (areas of the input mesh).
  EnergyTerms energy() const;
  int lloyd_iterations_done() const { return lloyd_done_; }
  int teleports_done() const { return teleports_; }
  bool converged() const { return converged_; }
  // Retries made so far in this solve (RemeshParams::retries); the solve in progress is
  // retry number retries_done() (0: the first).
  int retries_done() const { return retries_done_; }

 private:
  void validate(const RemeshParams& params) const;
  static bool same_solve(const RemeshParams& a, const RemeshParams& b);  // all but the edits
  void start_lloyd();
  void after_lloyd();
  void panel_round();
  // coverage: a valid attempt's coverage round (its collapsed clusters move elsewhere).
  void fix_panels(const PanelAttempt& attempt, bool coverage = false);
  bool coverage_round(std::unique_ptr<PanelAttempt>& attempt);  // true: the round is done
  void fit_planes(PanelAttempt& attempt);
  void optimize_planes();
  void finish_panels();
  // finish_panels with the coverage rounds' fallback (valid, fewest collapsed) as the best.
  void finish_with_fallback();
  // True: the panel rounds go on, working on the needles (remesher.cpp).
  bool start_needle_rounds();
  void finish_with_needle_fallback();
  // best_'s finished layout -> panels_, Done.
  void finish_layout();
  // The designer's minimum corner angle, or kNeedleRoundsDeg in the needle rounds.
  double min_corner_angle() const;
  void end_panels();  // the panel phase's result: the best attempt's panels, then Optimize or Done
  // At the end of a panel phase: keeps the better of this solve and the earlier ones, and
  // starts a retry from a new seeding when panels are invalid and retries are left (true).
  bool retry_if_invalid();
  // params().seed, or the retry's seed derived from it.
  std::uint64_t solve_seed() const;
  // A fresh solve from the Seeding stage (the clustering dropped).
  void start_over();
  void mend_best();  // last fixes on the best attempt when it is still invalid
  std::unique_ptr<PanelAttempt> make_attempt();  // the panel attempt of clustering_ now
  // remesher_polish.cpp: after mend_best, more attempts from the best, one per step().
  bool start_polish();  // false: nothing to polish (end_panels now)
  void polish_step();   // one attempt, or end_panels() when none is left
  // A pass's local splits and merges on the best attempt: split_requests' max_geometric, -1
  // for none (each invalid cluster halved). The pass's first attempt, or null (no n clusters).
  std::unique_ptr<PanelAttempt> polish_pass(int max_geometric);
  void keep_alternate(std::unique_ptr<PanelAttempt> attempt);
  void cut_glass();  // glass mode, last: the pieces of concave panels (glass_split.h)

  // Edits (remesher_edits.cpp). A held cluster keeps exactly these faces, and this plane (a
  // neighbour of the locked panel may turn it about their edge line: hinges()).
  struct Held {
    int face = -1;  // one of its held faces: its id is that face's label
    std::vector<int> faces;
    Plane plane;
  };
  // A locked cluster and the clusters around it (their planes make its outline): held[0] is
  // the locked one.
  struct Lock {
    std::vector<Held> held;
    // Its outline's nodes, each named by a face of each of its three clusters (-1: the border).
    std::vector<std::array<int, 3>> nodes;
    // Its corners' node groups made one point, each named by a face of each of its clusters.
    std::vector<std::vector<int>> single_groups;
    // Its corners' grouping (mesh vertices): pairs grouped, corners alone (corner_groups.h).
    HeldGrouping grouping;
    // The spike distance (world units) the design had when it was locked: its vertices keep
    // being judged by it (LayoutOptions::locked_spike_distance).
    double spike_distance = 0.0;
    double diameter = 0.0;  // and its D (world units): LayoutOptions::locked_diameter
  };
  // Everything an edit changes, to restore on failure or undo.
  struct EditState;
  EditState save() const;
  void restore(const EditState& state);
  void validate_edits(const std::vector<PanelEdit>& edits) const;
  void apply_pending_edits();
  void apply_edit(const PanelEdit& edit, size_t index);
  void start_edited_panels(const std::vector<int>& edited);
  void record_planes();
  void clear_edits();
  // Per cluster: held by a lock; and the held planes written into settled / planes.
  std::vector<char> held_clusters() const;
  void hold(std::vector<char>& settled, std::vector<Plane>& planes) const;
  std::vector<int> held_labels() const;  // per face: its held cluster, or -1
  std::vector<int> hinges() const;       // PanelAttemptOptions::hinge_of
  // LayoutOptions::locked_spike_distance and locked_diameter.
  void locked_limits(std::vector<double>& spike_distance, std::vector<double>& diameter) const;
  std::vector<std::array<int, 3>> held_nodes() const;  // LayoutOptions::held_nodes
  std::vector<std::vector<int>> held_single() const;   // LayoutOptions::held_single
  HeldGrouping held_grouping() const;                  // LayoutOptions::held_grouping
  void lloyd_step_held();
  // The parts of the surface (edge-connected) that the locks' held faces leave free.
  int free_parts_with_locks() const;
  void change_count_held(int target);

  TriMesh mesh_;
  MeshTopology topology_;
  RemeshParams params_;
  FaceData faces_;
  Metric metric_;
  Clustering clustering_;
  Progress progress_;
  std::vector<Vec3> local_positions_;   // mesh vertices in the frame of faces_
  double check_tolerance_ = 0.0;        // LayoutOptions::tolerance (local frame): see the constructor
  std::unique_ptr<PanelAttempt> best_;  // the attempt with the fewest invalid panels so far
  std::vector<std::unique_ptr<PanelAttempt>> alternates_;  // close runners-up (keep_alternate)
  ClusterMomentsCache moments_;         // the panel phase's cluster moments (faces_ and clustering_)
  PanelGraphState graph_state_;         // the last panel round's graph, updated for the next
  // The polish between steps (remesher_polish.cpp). Reset with best_ (a new panel phase,
  // a restored design): the attempts it refers to belong to one panel phase.
  struct PolishState {
    bool active = false;
    int pass = 0;      // the next pass to start (three in all)
    int attempts = 0;  // attempts of the pass so far
    // The next attempt continues the pass's chain of rounds: from `from`, or from best_
    // when `from` is null.
    bool chain = false;
    std::unique_ptr<PanelAttempt> from;
  };
  PolishState polish_;
  // Coverage rounds: a valid attempt with collapsed panels (PanelIssues::collapsed) is kept
  // as the fallback, and up to kCoverageRounds more rounds move its collapsed clusters
  // elsewhere; the run ends valid with the fewest collapsed panels found. Reset with best_.
  struct CoverageState {
    std::unique_ptr<PanelAttempt> fallback;
    int first_round = 0;  // the round of the first fallback
  };
  CoverageState coverage_;
  // Needle rounds: a finished valid result with a corner below kNeedleRoundsDeg (and no
  // minimum corner angle of the designer's) is kept as the fallback, and up to kNeedleRounds
  // more panel rounds treat such corners as panel problems; the first valid attempt then
  // ends the run (finished as usual), or the fallback does, as it was. Once per panel phase.
  // Reset with best_.
  struct NeedleState {
    std::unique_ptr<PanelAttempt> fallback;
    int first_round = 0;
    bool tried = false;
  };
  NeedleState needles_;
  // The best solve before the current retry (retry_if_invalid), with what the report says
  // about it. Empty outside a retry.
  struct EarlierSolve {
    std::unique_ptr<PanelAttempt> best;
    int lloyd_done = 0, teleports = 0, panel_rounds = 0;
    bool converged = false;
  };
  EarlierSolve earlier_;
  int retries_done_ = 0;
  PanelMesh panels_;
  int panel_rounds_done_ = 0;
  // Panel rounds since the fewest invalid panels went down or since the last stall split
  // (reset by both: it paces the splits); best_round_ is not reset by splits (it paces the
  // patience stop).
  int stalled_rounds_ = 0;
  // The invalid clusters of the last round whose early mend failed (kMendEarlyAt): a round
  // with the same ones skips the mend. A tail of rounds often waits on the same one to three
  // panels (a corner of four clusters on a saddle where neither pairing is valid), and the
  // mend then failed round after round: 43% of bunny.off's 40-round run at 200 panels, seed 7.
  // Over sweep_validity.sh's cases at seeds 1-3 the mend ran 667 times and succeeded 96; on
  // the same panels as its last failure, 5 times in 123.
  std::vector<int> failed_mend_;
  int best_round_ = 0;  // the panel round that last lowered the fewest invalid panels
  // Per cluster: valid among valid panels in the last round, so it keeps its faces and plane.
  std::vector<char> settled_;
  std::vector<Plane> settled_planes_;  // per cluster: its plane in the last round
  int lloyd_done_ = 0;
  int teleports_ = 0;
  bool converged_ = false;
  // Edits: planes per cluster of the finished design, locks, edits applied so far, the edits
  // already in the design when the parameters last changed, and the design before the first
  // edit after that (the base undo and redo replay from).
  std::vector<Plane> cluster_planes_;
  std::vector<CornerNodes> cluster_nodes_;  // per cluster: its corners' nodes and one-point groups
  std::vector<Lock> locks_;
  size_t next_edit_ = 0;
  size_t base_edits_ = 0;
  std::shared_ptr<const EditState> base_;
};

}  // namespace ff
