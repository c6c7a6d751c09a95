#include "core/remesher.h"

#include <algorithm>
#include <optional>

#include "core/cluster/lloyd.h"
#include "core/cluster/teleport.h"
#include "core/util/error.h"

namespace ff {

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::Seeding:
      return "seeding";
    case Stage::Lloyd:
      return "lloyd";
    case Stage::Done:
      return "done";
  }
  return "unknown";
}

namespace {
constexpr int kMaxIterations = 100000;
}

Remesher::Remesher(TriMesh mesh, RemeshParams params)
    : mesh_(std::move(mesh)),
      topology_(build_topology(mesh_)),
      params_(std::move(params)),
      faces_(make_face_data(mesh_, params_.density)),
      metric_(faces_, params_.weights, std::max(1, params_.panels)) {
  validate(params_);
  progress_ = Progress{Stage::Seeding, 0, 1, 0.0, 0};
}

void Remesher::validate(const RemeshParams& p) const {
  if (p.panels < 1) throw InputError("the number of panels must be at least 1");
  if (p.lloyd_iterations < 0 || p.lloyd_iterations > kMaxIterations)
    throw InputError("iterations must be between 0 and " + std::to_string(kMaxIterations));
  if (p.teleport_interval < 0 || p.teleport_moves < 0) throw InputError("teleport interval and moves must be >= 0");
  seeds_per_component(faces_, topology_, p.panels);  // throws on too many / too few panels
}

void Remesher::start_lloyd() {
  lloyd_done_ = 0;
  converged_ = false;
  progress_ = Progress{Stage::Lloyd, 0, params_.lloyd_iterations, clustering_.energy * faces_.area_to_world(), 0};
  if (params_.lloyd_iterations == 0) progress_.stage = Stage::Done;
}

Progress Remesher::step() {
  switch (progress_.stage) {
    case Stage::Seeding: {
      const std::vector<int> seeds =
          place_seeds(faces_, topology_, params_.panels, params_.seeding, params_.seed, params_.weights.density);
      clustering_ = initial_clustering(metric_, topology_, seeds);
      start_lloyd();
      break;
    }
    case Stage::Lloyd: {
      const int it = lloyd_done_ + 1;
      int moves = 0;
      // Teleport early and mid-phase, never in the last iterations, so Lloyd settles after.
      if (params_.teleport_interval > 0 && it % params_.teleport_interval == 0 && it + 2 <= params_.lloyd_iterations) {
        TeleportOptions options;
        options.max_moves = params_.teleport_moves > 0 ? params_.teleport_moves : std::max(1, params_.panels / 64);
        moves = teleport(metric_, topology_, clustering_, options);
        teleports_ += moves;
      }
      // A teleport refloods and refits, which is this iteration's work; otherwise one Lloyd step.
      if (moves == 0) {
        const LloydResult r = lloyd_iteration(metric_, topology_, clustering_);
        if (r.changed_faces == 0) converged_ = true;
      }
      lloyd_done_ = it;
      progress_.iteration = it;
      progress_.energy = clustering_.energy * faces_.area_to_world();
      if (converged_ || it >= params_.lloyd_iterations) progress_.stage = Stage::Done;
      break;
    }
    case Stage::Done:
      break;
  }
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
  if (params.density != params_.density) faces = make_face_data(mesh_, params.density);
  Metric(faces ? *faces : faces_, params.weights, params.panels);  // throws on bad weights
  const bool restart = clustering_.labels.empty() || params.seed != params_.seed || params.seeding != params_.seeding;
  const int old_panels = params_.panels;
  params_ = std::move(params);
  if (faces) faces_ = std::move(*faces);
  metric_ = Metric(faces_, params_.weights, params_.panels);
  if (restart) {
    clustering_ = Clustering{};
    teleports_ = 0;
    lloyd_done_ = 0;
    converged_ = false;
    progress_ = Progress{Stage::Seeding, 0, 1, 0.0, 0};
    return;
  }
  if (params_.panels > old_panels) add_clusters(metric_, topology_, clustering_, params_.panels - old_panels);
  if (params_.panels < old_panels) remove_clusters(metric_, topology_, clustering_, old_panels - params_.panels);
  if (params_.panels == old_panels) refit(metric_, clustering_);  // proxies and energy under the new metric
  start_lloyd();
}

}  // namespace ff
