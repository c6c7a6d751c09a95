// A PanelLayout built with build_panels = false (the panel attempt's layouts, whose planes the
// relaxation replaces at once) must end, after set_planes(), exactly (bit for bit) as one
// that built its panels in the constructor and then rebuilt those the new planes reach:
// where some planes moved, where none did, and with every plane moved.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/cluster/lloyd.h"
#include "core/cluster/metric.h"
#include "core/cluster/seeding.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_attempt.h"
#include "remesh_checks.h"

namespace ff {
namespace {

void expect_same_panels(const PanelLayout& a, const PanelLayout& b) {
  ASSERT_EQ(a.num_clusters(), b.num_clusters());
  EXPECT_EQ(a.num_invalid(), b.num_invalid());
  for (int c = 0; c < a.num_clusters(); ++c) {
    const PanelPolygon& p = a.polygon(c);
    const PanelPolygon& q = b.polygon(c);
    ASSERT_EQ(p.points.size(), q.points.size()) << "panel " << c;
    for (size_t i = 0; i < p.points.size(); ++i) {
      EXPECT_EQ(p.points[i].x(), q.points[i].x()) << "panel " << c;
      EXPECT_EQ(p.points[i].y(), q.points[i].y()) << "panel " << c;
      EXPECT_EQ(p.points[i].z(), q.points[i].z()) << "panel " << c;
      EXPECT_EQ(p.reference[i].x(), q.reference[i].x()) << "panel " << c;
    }
    EXPECT_EQ(p.node, q.node) << "panel " << c;
    EXPECT_EQ(p.corner, q.corner) << "panel " << c;
    const PanelIssues& x = a.issues()[static_cast<size_t>(c)];
    const PanelIssues& y = b.issues()[static_cast<size_t>(c)];
    EXPECT_EQ(x.valid(), y.valid()) << "panel " << c;
    EXPECT_EQ(x.not_disk, y.not_disk) << "panel " << c;
    EXPECT_EQ(x.spike_vertices, y.spike_vertices) << "panel " << c;
    EXPECT_EQ(x.flipped, y.flipped) << "panel " << c;
    EXPECT_EQ(x.not_star, y.not_star) << "panel " << c;
    EXPECT_EQ(x.not_simple, y.not_simple) << "panel " << c;
  }
  const std::vector<NodeConstraint> m = a.node_constraints(), n = b.node_constraints();
  ASSERT_EQ(m.size(), n.size());
  EXPECT_EQ(a.spike_nodes(), b.spike_nodes());
}

// The bunny at 200 panels after 10 Lloyd iterations, and a first attempt's masters.
struct Bunny {
  TriMesh mesh = test::load_clean("bunny.off");
  MeshTopology topology = build_topology(mesh);
  FaceData faces = make_face_data(mesh);
  std::vector<Vec3> positions;
  Clustering clustering;
  std::unique_ptr<PanelAttempt> attempt;
  LayoutOptions options;

  Bunny() {
    const Metric metric(faces, MetricWeights{}, 200);
    clustering =
        initial_clustering(metric, topology, place_seeds(faces, topology, 200, SeedingMethod::FarthestPoint, 1));
    for (int it = 0; it < 10; ++it) lloyd_iteration(metric, topology, clustering);
    for (const Vec3& p : mesh.positions) positions.push_back((p - faces.origin) / faces.scale);
    PanelAttemptOptions attempt_options;
    attempt_options.layout.diameter = metric.diameter();
    attempt_options.unsnap_rounds = 0;
    attempt_options.tilt_rounds = 0;
    attempt = std::make_unique<PanelAttempt>(mesh, topology, positions, faces, clustering, attempt_options);
    options = attempt_options.layout;
    options.spike_distance = 0.2 * metric.diameter();
  }
  std::unique_ptr<PanelLayout> layout(const MasterPlanes& planes, bool build) const {
    return std::make_unique<PanelLayout>(mesh, topology, attempt->clustering().labels, positions, attempt->graph(),
                                         planes, options, std::vector<std::pair<int, int>>{}, build);
  }
};

TEST(LayoutDeferred, SetPlanesBuildsAsTheConstructorAndARebuild) {
  const Bunny b;
  const MasterPlanes relaxed = b.attempt->layout().planes();
  // The constructor's planes: two masters in three moved off the relaxed ones.
  MasterPlanes start = relaxed;
  for (size_t m = 0; m < start.planes.size(); ++m) start.planes[m].offset += 1e-3 * static_cast<double>(m % 3);
  const std::vector<const std::vector<Plane>*> targets = {&relaxed.planes, &start.planes};
  for (const std::vector<Plane>* target : targets) {
    auto built = b.layout(start, true);
    auto deferred = b.layout(start, false);
    built->set_planes(*target);
    deferred->set_planes(*target);
    expect_same_panels(*built, *deferred);
    // And the layout goes on as usual: another change rebuilds what it reaches, the same way.
    std::vector<Plane> moved = *target;
    moved[0].offset += 2e-3;
    built->set_planes(moved);
    deferred->set_planes(moved);
    expect_same_panels(*built, *deferred);
  }
  // Some panels are invalid on these planes: the comparison covers the checks' flags too.
  auto built = b.layout(start, true);
  EXPECT_GT(built->num_invalid(), 0);
}

}  // namespace
}  // namespace ff
