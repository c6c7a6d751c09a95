// The layout's shortcuts that keep panels instead of building them again (panel_fixes.cpp):
// try_planes puts a refused plane's panels back from saved copies, stops a trial once it is
// refused, and skips planes whose surroundings did not change since they were refused;
// switch_pairings puts the panels of a kept pairing back and keeps the last trial's panels
// when that is the pairing chosen. Each must leave every panel exactly (bit for bit) as a
// fresh build from the final planes and pairings gives.
#include <gtest/gtest.h>

#include <vector>

#include "core/cluster/lloyd.h"
#include "core/cluster/metric.h"
#include "core/cluster/seeding.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_attempt.h"
#include "core/panels/plane_fit.h"
#include "remesh_checks.h"

namespace ff {
namespace {

// Every panel of `layout` against a rebuild of all of them: the planes moved away and back
// (set_planes builds every group and panel a changed plane reaches, here all).
void expect_as_built_fresh(const PanelLayout& layout) {
  PanelLayout fresh = layout;
  std::vector<Plane> moved = layout.planes().planes;
  for (Plane& p : moved) p.offset += 1e-3;
  fresh.set_planes(moved);
  fresh.set_planes(layout.planes().planes);
  ASSERT_EQ(fresh.num_clusters(), layout.num_clusters());
  for (int c = 0; c < layout.num_clusters(); ++c) {
    const PanelPolygon& a = layout.polygon(c);
    const PanelPolygon& b = fresh.polygon(c);
    ASSERT_EQ(a.points.size(), b.points.size()) << "panel " << c;
    for (size_t i = 0; i < a.points.size(); ++i) {
      // Exact: the same operations on the same planes.
      EXPECT_EQ(a.points[i].x(), b.points[i].x()) << "panel " << c;
      EXPECT_EQ(a.points[i].y(), b.points[i].y()) << "panel " << c;
      EXPECT_EQ(a.points[i].z(), b.points[i].z()) << "panel " << c;
    }
    EXPECT_EQ(a.node, b.node) << "panel " << c;
    EXPECT_EQ(a.corner, b.corner) << "panel " << c;
    const PanelIssues& x = layout.issues()[static_cast<size_t>(c)];
    const PanelIssues& y = fresh.issues()[static_cast<size_t>(c)];
    EXPECT_EQ(x.valid(), y.valid()) << "panel " << c;
    EXPECT_EQ(x.spike_vertices, y.spike_vertices) << "panel " << c;
    EXPECT_EQ(x.flipped, y.flipped) << "panel " << c;
    EXPECT_EQ(x.not_star, y.not_star) << "panel " << c;
    EXPECT_EQ(x.not_simple, y.not_simple) << "panel " << c;
  }
}

// A first panel attempt on the bunny at 200 panels (Lloyd as in the remesher), with no
// fixes after the relaxation, so some panels are invalid and pairings have work to do.
struct BunnyAttempt {
  TriMesh mesh = test::load_clean("bunny.off");
  MeshTopology topology = build_topology(mesh);
  FaceData faces = make_face_data(mesh);
  std::vector<Vec3> positions;
  Clustering clustering;
  std::unique_ptr<PanelAttempt> attempt;

  BunnyAttempt() {
    const Metric metric(faces, MetricWeights{}, 200);
    clustering = initial_clustering(metric, topology, place_seeds(faces, topology, 200, SeedingMethod::FarthestPoint, 1));
    for (int it = 0; it < 10; ++it) lloyd_iteration(metric, topology, clustering);
    for (const Vec3& p : mesh.positions) positions.push_back((p - faces.origin) / faces.scale);
    PanelAttemptOptions options;
    options.layout.diameter = metric.diameter();
    options.unsnap_rounds = 0;
    options.tilt_rounds = 0;
    attempt = std::make_unique<PanelAttempt>(mesh, topology, positions, faces, clustering, options);
  }
};

TEST(LayoutReuse, TryPlanesLeavesPanelsAsAFreshBuild) {
  BunnyAttempt b;
  const PanelLayout& start = b.attempt->layout();
  // The final fit's candidates (as Remesher::optimize_planes), and the same halfway.
  const std::vector<Plane> fitted =
      surface_fit_planes(b.faces, b.clustering.labels, start.planes(), start.node_constraints());
  PanelLayout layout = start;
  const int invalid = layout.num_invalid();
  const int kept = layout.try_planes(fitted, 2);
  EXPECT_GT(kept, 0);
  // Some refused (else nothing was undone): not every plane is the fitted one.
  int refused = 0;
  for (size_t m = 0; m < fitted.size(); ++m) {
    const Plane& p = layout.planes().planes[m];
    refused += p.normal == fitted[m].normal && p.offset == fitted[m].offset ? 0 : 1;
  }
  EXPECT_GT(refused, 0);
  EXPECT_LE(layout.num_invalid(), invalid);  // a plane is kept only where it adds none
  expect_as_built_fresh(layout);
  layout.try_planes(planes_toward(layout.planes().planes, fitted, 0.5));
  expect_as_built_fresh(layout);
}

TEST(LayoutReuse, TryPlanesTwoPassesAsTwoCalls) {
  BunnyAttempt b;
  const PanelLayout& start = b.attempt->layout();
  const std::vector<Plane> fitted =
      surface_fit_planes(b.faces, b.clustering.labels, start.planes(), start.node_constraints());
  PanelLayout twice = start, calls = start;
  twice.try_planes(fitted, 2);
  if (calls.try_planes(fitted) > 0) calls.try_planes(fitted);
  for (size_t m = 0; m < fitted.size(); ++m) {
    EXPECT_EQ(twice.planes().planes[m].normal, calls.planes().planes[m].normal) << "master " << m;
    EXPECT_EQ(twice.planes().planes[m].offset, calls.planes().planes[m].offset) << "master " << m;
  }
}

TEST(LayoutReuse, SwitchPairingsLeavesPanelsAsAFreshBuild) {
  BunnyAttempt b;
  PanelLayout layout = b.attempt->layout();
  ASSERT_GT(layout.num_invalid(), 0);
  const int invalid = layout.num_invalid();
  layout.switch_pairings();
  EXPECT_LE(layout.num_invalid(), invalid);
  expect_as_built_fresh(layout);
}

}  // namespace
}  // namespace ff
