// Each panel's deviation from the design (core/quality/panel_deviation.h): a known answer on
// flat panels lifted off a flat input, a panel lifted higher than its neighbours standing out,
// and a real solve whose largest deviation matches the report's Hausdorff distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/mesh/topology.h"
#include "core/quality/panel_deviation.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"

namespace ff {
namespace {

// The input: a flat 3 x 2 rectangle at z = 0. The panels: its four 1.5 x 1 quarters, each on
// its own vertices, at the given heights; each input triangle belongs to the quarter holding
// its centroid.
struct Quarters {
  TriMesh input;
  PanelMesh panels;
};

Quarters quarters(const double (&height)[4]) {
  Quarters q;
  q.input = make_grid_surface(12, 8, [](double u, double v) { return Vec3(3.0 * u, 2.0 * v, 0.0); });
  for (int p = 0; p < 4; ++p) {
    const double x0 = 1.5 * (p % 2), y0 = 1.0 * (p / 2), z = height[p];
    const int base = static_cast<int>(q.panels.vertices.size());
    for (const auto& [x, y] : {std::pair{x0, y0}, {x0 + 1.5, y0}, {x0 + 1.5, y0 + 1.0}, {x0, y0 + 1.0}})
      q.panels.vertices.emplace_back(x, y, z);
    q.panels.panels.push_back({base, base + 1, base + 2, base + 3});
  }
  for (int f = 0; f < q.input.num_faces(); ++f) {
    const Vec3 c = face_centroid(q.input, f);
    q.panels.face_panel.push_back((c.x() < 1.5 ? 0 : 1) + (c.y() < 1.0 ? 0 : 2));
  }
  return q;
}

TEST(PanelDeviation, LiftedPanelsDeviateByTheirHeight) {
  const Quarters q = quarters({0.25, 0.25, 0.25, 0.25});
  const double diagonal = bbox_diagonal(q.input);
  const std::vector<double> d = panel_deviation(q.input, q.panels);
  ASSERT_EQ(d.size(), 4u);
  for (double x : d) EXPECT_NEAR(x, 0.25 / diagonal, 1e-12);
}

TEST(PanelDeviation, APanelLiftedHigherStandsOut) {
  const Quarters q = quarters({0.25, 0.25, 0.25, 0.5});
  const double diagonal = bbox_diagonal(q.input);
  const std::vector<double> d = panel_deviation(q.input, q.panels);
  for (int p = 0; p < 3; ++p) EXPECT_NEAR(d[static_cast<size_t>(p)], 0.25 / diagonal, 1e-12) << "panel " << p;
  // Its own points are 0.5 above the input; the input's points under it are at most 0.5 from
  // it (those near its neighbours are closer to them).
  EXPECT_NEAR(d[3], 0.5 / diagonal, 1e-12);
}

// A real solve: the largest panel deviation is the report's Hausdorff distance at a coarser
// sampling, and the panels differ (the view has something to show).
TEST(PanelDeviation, ItsMaximumIsTheHausdorffDistance) {
  const TriMesh mesh = make_saddle(4000);
  RemeshParams params;
  params.panels = 40;
  Remesher r(mesh, params);
  while (!r.done()) r.step();
  const std::vector<double> d = panel_deviation(r.mesh(), r.panels());
  ASSERT_EQ(d.size(), static_cast<size_t>(r.panels().num_panels()));
  for (double x : d) EXPECT_TRUE(std::isfinite(x) && x >= 0.0);
  const QualityReport report = measure_quality(r.mesh(), build_topology(r.mesh()), r.panels());
  const double largest = *std::max_element(d.begin(), d.end());
  EXPECT_NEAR(largest, report.hausdorff, 0.1 * report.hausdorff);
  EXPECT_LT(*std::min_element(d.begin(), d.end()), 0.8 * largest);
}

TEST(PanelDeviation, ClearErrors) {
  Quarters q = quarters({0.25, 0.25, 0.25, 0.25});
  EXPECT_THROW(panel_deviation(q.input, q.panels, -1), InputError);
  EXPECT_THROW(panel_deviation(TriMesh{}, q.panels), InputError);
  q.panels.face_panel.pop_back();
  EXPECT_THROW(panel_deviation(q.input, q.panels), InputError);
  EXPECT_EQ(panel_deviation(q.input, PanelMesh{}), std::vector<double>{});
}

}  // namespace
}  // namespace ff
