// The boundary term of the panel phase (core/panels/boundary_term.h, paper 3.2): zero for a
// face whose centroid projects inside the cluster's panel, else area * weight * (distance to
// the panel's boundary) / (D / 50); ignored clusters add nothing, frozen ones keep their faces.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/panels/boundary_term.h"
#include "core/panels/panel_layout.h"
#include "labelled_grid.h"

namespace ff {
namespace {

// A 6 x 4 grid of unit cells in two clusters, L (0, x < 3) on z = 0 and R (1, x > 3) on a
// plane through the line x = 3 tilted about it. L's panel is exactly the rectangle
// [0, 3] x [0, 4] on z = 0, so distances to it can be worked out by hand.
struct Split : test::LabelledGrid {
  Split() : LabelledGrid(test::labelled_grid(test::grid(6, 4), 2, [](const Vec3& c) { return c.x() < 3.0 ? 0 : 1; })) {}

  PanelLayout layout() const {
    MasterPlanes m;
    m.master_of = {0, 1};
    m.planes = {Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1)),
                Plane::through(Vec3(3, 0, 0), Vec3(-0.2, 0, 1).normalized())};
    m.centers = {Vec3(1.5, 2, 0), m.planes[1].project(Vec3(4.5, 2, 0))};
    m.count = {1, 1};
    LayoutOptions options;
    options.diameter = 2.0;
    options.spike_distance = 1.0;
    return PanelLayout(mesh, topology, labels, mesh.positions, graph, std::move(m), options);
  }
};

// Faces that are just a centroid and an area: all the term reads of them.
FaceData probes(const std::vector<Vec3>& centroids, double area) {
  FaceData data;
  for (const Vec3& c : centroids) {
    FaceRecord r;
    r.centroid = c;
    r.area = area;
    data.records.push_back(r);
  }
  return data;
}

TEST(BoundaryTerm, ZeroUnderOwnPanel) {
  const Split s;
  const PanelLayout layout = s.layout();
  ASSERT_EQ(layout.num_invalid(), 0);
  std::vector<Vec3> centroids;
  for (int f = 0; f < s.mesh.num_faces(); ++f) centroids.push_back(face_centroid(s.mesh, f));
  const FaceData faces = probes(centroids, 0.5);
  const BoundaryTerm term(faces, layout, 1.0, 2.0);
  // Every face lies under its own cluster's panel (R's too, once projected on its tilted
  // plane), and outside the other one's.
  for (int f = 0; f < s.mesh.num_faces(); ++f) {
    const int own = s.labels[static_cast<size_t>(f)];
    EXPECT_EQ(term(f, own), 0.0) << f;
    EXPECT_GT(term(f, 1 - own), 0.0) << f;
  }
}

// Outside L's rectangle: area 0.5 * weight 1 / (2 / 50) = 12.5 per unit of distance.
TEST(BoundaryTerm, DistanceOutsideThePanel) {
  const Split s;
  const PanelLayout layout = s.layout();
  const FaceData faces = probes({Vec3(3.5, 2, 0), Vec3(4, 2, 0), Vec3(4.5, 2, 0), Vec3(4, 2, 0.7), Vec3(4, 5, 0)}, 0.5);
  const BoundaryTerm term(faces, layout, 1.0, 2.0);
  EXPECT_NEAR(term(0, 0), 12.5 * 0.5, 1e-9);
  EXPECT_NEAR(term(1, 0), 12.5 * 1.0, 1e-9);
  EXPECT_NEAR(term(2, 0), 12.5 * 1.5, 1e-9);
  EXPECT_NEAR(term(3, 0), 12.5 * 1.0, 1e-9);             // height above the plane does not count
  EXPECT_NEAR(term(4, 0), 12.5 * std::sqrt(2.0), 1e-9);  // nearest the corner (3, 4)
}

// The length unit is D / 50 and the cost is linear in weight and area; no weight, no term.
TEST(BoundaryTerm, ScalesWithWeightAreaAndDiameter) {
  const Split s;
  const PanelLayout layout = s.layout();
  const FaceData small = probes({Vec3(4, 2, 0)}, 0.5), large = probes({Vec3(4, 2, 0)}, 1.5);
  const double base = BoundaryTerm(small, layout, 1.0, 2.0)(0, 0);
  ASSERT_GT(base, 0.0);
  EXPECT_NEAR(base, 0.5 * 1.0 / (BoundaryTerm::kLengthUnit * 2.0), 1e-9);
  EXPECT_NEAR(BoundaryTerm(small, layout, 3.0, 2.0)(0, 0), 3.0 * base, 1e-9);
  EXPECT_NEAR(BoundaryTerm(large, layout, 1.0, 2.0)(0, 0), 3.0 * base, 1e-9);
  EXPECT_NEAR(BoundaryTerm(small, layout, 1.0, 4.0)(0, 0), 0.5 * base, 1e-9);
  EXPECT_EQ(BoundaryTerm(small, layout, 0.0, 2.0)(0, 0), 0.0);
  EXPECT_EQ(BoundaryTerm(small, layout, 1.0, 0.0)(0, 0), 0.0);  // no diameter: off, not infinite
}

TEST(BoundaryTerm, IgnoredClusterAddsNothing) {
  const Split s;
  const PanelLayout layout = s.layout();
  const FaceData faces = probes({Vec3(4, 2, 0), Vec3(1, 2, 0)}, 0.5);
  BoundaryTerm term(faces, layout, 1.0, 2.0);
  ASSERT_GT(term(0, 0), 0.0);
  ASSERT_GT(term(1, 1), 0.0);
  term.ignore(0);
  term.ignore(7);  // out of range: a no-op
  EXPECT_EQ(term(0, 0), 0.0);
  EXPECT_GT(term(1, 1), 0.0);  // the other cluster keeps its term
}

// Frozen (settled) clusters keep exactly their faces: moves into or out of them are forbidden.
TEST(BoundaryTerm, FrozenClustersKeepTheirFaces) {
  const Split s;
  const PanelLayout layout = s.layout();
  const FaceData faces = probes({Vec3(1, 2, 0), Vec3(4, 2, 0)}, 0.5);
  BoundaryTerm term(faces, layout, 1.0, 2.0);
  EXPECT_EQ(term.fixed_label(0), -1);  // nothing frozen yet
  term.freeze({1, 0}, {0, 1});         // L settled; face 0 in L, face 1 in R
  EXPECT_EQ(term.fixed_label(0), 0);
  EXPECT_EQ(term.fixed_label(1), -1);
  EXPECT_EQ(term(0, 1), BoundaryTerm::kForbidden);  // out of L
  EXPECT_EQ(term(1, 0), BoundaryTerm::kForbidden);  // into L
  EXPECT_EQ(term(0, 0), 0.0);                       // staying costs the usual
  EXPECT_EQ(term(1, 1), 0.0);
}

}  // namespace
}  // namespace ff
