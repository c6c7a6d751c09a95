// A first panel attempt on the bunny at 200 panels (Lloyd as in the remesher), with no
// fixes after the relaxation, so some panels are invalid and the fixes have work to do; and
// the bit-for-bit panel comparison the tests on it use.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/cluster/lloyd.h"
#include "core/cluster/metric.h"
#include "core/cluster/seeding.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_attempt.h"
#include "core/panels/panel_layout.h"
#include "remesh_checks.h"

namespace ff::test {

struct BunnyAttempt {
  TriMesh mesh = load_clean("bunny.off");
  MeshTopology topology = build_topology(mesh);
  FaceData faces = make_face_data(mesh);
  std::vector<Vec3> positions;
  Clustering clustering;
  std::unique_ptr<PanelAttempt> attempt;
  double diameter = 0.0;  // the metric's expected cluster diameter

  BunnyAttempt() {
    const Metric metric(faces, MetricWeights{}, 200);
    clustering =
        initial_clustering(metric, topology, place_seeds(faces, topology, 200, SeedingMethod::FarthestPoint, 1));
    for (int it = 0; it < 10; ++it) lloyd_iteration(metric, topology, clustering);
    for (const Vec3& p : mesh.positions) positions.push_back((p - faces.origin) / faces.scale);
    PanelAttemptOptions options;
    diameter = metric.diameter();
    options.layout.diameter = diameter;
    options.unsnap_rounds = 0;
    options.tilt_rounds = 0;
    attempt = std::make_unique<PanelAttempt>(mesh, topology, positions, faces, clustering, options);
  }
};

// Every panel of `fresh` equals `layout`'s bit for bit: points, references, nodes, corners
// and issues.
inline void expect_same_panels(const PanelLayout& layout, const PanelLayout& fresh) {
  ASSERT_EQ(fresh.num_clusters(), layout.num_clusters());
  EXPECT_EQ(fresh.num_invalid(), layout.num_invalid());
  for (int c = 0; c < layout.num_clusters(); ++c) {
    const PanelPolygon& a = layout.polygon(c);
    const PanelPolygon& b = fresh.polygon(c);
    ASSERT_EQ(a.points.size(), b.points.size()) << "panel " << c;
    for (size_t i = 0; i < a.points.size(); ++i) {
      // Exact: the same operations on the same planes.
      EXPECT_EQ(a.points[i].x(), b.points[i].x()) << "panel " << c;
      EXPECT_EQ(a.points[i].y(), b.points[i].y()) << "panel " << c;
      EXPECT_EQ(a.points[i].z(), b.points[i].z()) << "panel " << c;
      EXPECT_EQ(a.reference[i], b.reference[i]) << "panel " << c;
    }
    EXPECT_EQ(a.node, b.node) << "panel " << c;
    EXPECT_EQ(a.corner, b.corner) << "panel " << c;
    const PanelIssues& x = layout.issues()[static_cast<size_t>(c)];
    const PanelIssues& y = fresh.issues()[static_cast<size_t>(c)];
    EXPECT_EQ(x.valid(), y.valid()) << "panel " << c;
    EXPECT_EQ(x.not_disk, y.not_disk) << "panel " << c;
    EXPECT_EQ(x.spike_vertices, y.spike_vertices) << "panel " << c;
    EXPECT_EQ(x.flipped, y.flipped) << "panel " << c;
    EXPECT_EQ(x.not_star, y.not_star) << "panel " << c;
    EXPECT_EQ(x.not_simple, y.not_simple) << "panel " << c;
  }
}

// Every panel of `layout` against a rebuild of all of them: the planes moved away and back
// (set_planes builds every group and panel a changed plane reaches, here all).
inline void expect_as_built_fresh(const PanelLayout& layout) {
  PanelLayout fresh = layout;
  std::vector<Plane> moved = layout.planes().planes;
  for (Plane& p : moved) p.offset += 1e-3;
  fresh.set_planes(moved);
  fresh.set_planes(layout.planes().planes);
  expect_same_panels(layout, fresh);
}

}  // namespace ff::test
