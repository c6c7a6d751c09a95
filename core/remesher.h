#pragma once
// Remesher: the pipeline as a resumable state machine (DESIGN.md 2). step() does bounded
// work (seeding, or one Lloyd iteration) and returns Progress, so the CLI, the tests and the
// web worker drive the same object and can stop, report or change parameters between steps.
//
// Stages: Seeding -> Lloyd (k1 iterations, teleports every few) -> Panels (up to k2 rounds of
// corners -> intersect planes -> validate -> fix -> Lloyd with the boundary term) ->
// Optimize (the planes themselves, least squares, once the combinatorics settled) -> Done.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/face_data.h"
#include "core/cluster/metric.h"
#include "core/cluster/seeding.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_attempt.h"
#include "core/panels/panel_mesh.h"

namespace ff {

struct RemeshParams {
  int panels = 100;
  std::uint64_t seed = 1;
  MetricWeights weights;
  // Empty (uniform), one value per mesh vertex or one per face; higher = smaller panels.
  std::vector<double> density;
  int lloyd_iterations = 20;  // k1: an upper bound; stops earlier at a fixed point
  SeedingMethod seeding = SeedingMethod::FarthestPoint;
  int teleport_interval = 4;  // teleport before every 4th iteration; 0 = never
  int teleport_moves = 0;     // moves per teleport; 0 = automatic (1 per 64 clusters, >= 1)
  bool make_panels = true;    // false: stop after the Lloyd phase (`flatfacet cluster`)
  int panel_rounds = 30;      // k2: an upper bound; stops at the first valid panel mesh
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
};

enum class Stage { Seeding, Lloyd, Panels, Optimize, Done };
const char* stage_name(Stage stage);

struct Progress {
  Stage stage = Stage::Seeding;
  int iteration = 0;  // within the stage
  int of = 0;         // the stage's iteration limit
  double energy = 0.0;
  int invalid_panels = 0;
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
  bool done() const { return progress_.stage == Stage::Done; }
  // Steps until done; returns the final progress.
  Progress run();
  const Progress& progress() const { return progress_; }

  // New parameters, warm-started from the current clustering: a changed panel count splits
  // the worst or merges the cheapest clusters, changed weights or density refit the proxies;
  // then the Lloyd phase runs again. A changed seed or seeding method starts over (and the
  // clustering is empty until the next step()). Throws InputError for bad parameters and
  // then leaves everything as it was.
  void set_params(RemeshParams params);

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

 private:
  void validate(const RemeshParams& params) const;
  void start_lloyd();
  void after_lloyd();
  void panel_round();
  void fix_panels(const PanelAttempt& attempt);
  void optimize_planes();
  void finish_panels();
  void cut_glass();  // glass mode, last: the pieces of concave panels (glass_split.h)

  TriMesh mesh_;
  MeshTopology topology_;
  RemeshParams params_;
  FaceData faces_;
  Metric metric_;
  Clustering clustering_;
  Progress progress_;
  std::vector<Vec3> local_positions_;   // mesh vertices in the frame of faces_
  std::unique_ptr<PanelAttempt> best_;  // the attempt with the fewest invalid panels so far
  PanelMesh panels_;
  int panel_rounds_done_ = 0;
  int stalled_rounds_ = 0;  // panel rounds since the fewest invalid panels went down
  // Per cluster: valid among valid panels in the last round, so it keeps its faces and plane.
  std::vector<char> settled_;
  std::vector<Plane> settled_planes_;  // per cluster: its plane in the last round
  int lloyd_done_ = 0;
  int teleports_ = 0;
  bool converged_ = false;
};

}  // namespace ff
