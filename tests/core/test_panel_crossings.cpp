// panel_crossings (core/panels/panel_crossings.h): panels that pass through each other in
// space, on hand-made panels whose answer is known, and on cow.off, where the panel phase
// leaves such pairs (reported by the quality check, bench/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/panels/panel_crossings.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "test_meshes.h"

namespace ff {
namespace {

struct Panels {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> panels;
  std::vector<Vec3> normals;
  std::vector<double> offsets;

  // A panel from its corners (planar, counter-clockwise about `normal`).
  void add(const std::vector<Vec3>& corners, const Vec3& normal) {
    std::vector<int> ids;
    for (const Vec3& c : corners) {
      ids.push_back(static_cast<int>(vertices.size()));
      vertices.push_back(c);
    }
    panels.push_back(ids);
    normals.push_back(normal.normalized());
    offsets.push_back(normal.normalized().dot(corners[0]));
  }
  std::vector<PanelCrossing> crossings() const { return panel_crossings(vertices, panels, normals, offsets); }
};

// The quality report of a shared mesh solved into `panels` panels with the defaults (seed 1).
QualityReport solved_quality(const std::string& mesh, int panels) {
  RemeshParams params;
  params.panels = panels;
  Remesher remesher(test::load_clean(mesh), params);
  remesher.run();
  return measure_quality(remesher.mesh(), remesher.topology(), remesher.panels());
}

TEST(PanelCrossings, TwoSquaresThroughEachOtherCross) {
  Panels p;
  p.add({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 0, 1});  // z = 0
  p.add({{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, {0, 1, 0});  // y = 0, through it
  const std::vector<PanelCrossing> c = p.crossings();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].a, 0);
  EXPECT_EQ(c[0].b, 1);
  // The line x from -1 to 1 at y = z = 0 is inside both; its middle is 1 from both outlines.
  EXPECT_NEAR(c[0].depth, 1.0, 0.07);
  EXPECT_NEAR(c[0].point.y(), 0.0, 1e-12);
  EXPECT_NEAR(c[0].point.z(), 0.0, 1e-12);
}

TEST(PanelCrossings, PanelsMeetingAlongAnEdgeOrAtACornerDoNotCross) {
  Panels p;
  p.add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1});
  p.add({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, {-1, 0, 0});   // folded up along x = 1
  p.add({{0, 1, 0}, {-1, 2, 1}, {-1, 2, 0}}, {1, 1, 0});             // touches at (0, 1, 0) only
  p.add({{0, 0, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0}}, {0, 0, 1});  // the same plane as the first
  EXPECT_TRUE(p.crossings().empty());
}

TEST(PanelCrossings, AConcavePanelIsCrossedInTwoStretches) {
  // A U-shaped panel (concave) in z = 0; the plane y = 0.5 meets it in two stretches, one per
  // arm, with the gap between them outside it.
  Panels p;
  p.add({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, {0, 0, 1});
  // A panel in the plane y = 0.5 through the U's two arms (x from -1 to 4), hanging below it
  // and rising above: it passes through both arms, not through the gap between them.
  p.add({{-1, 0.5, -1}, {4, 0.5, -1}, {4, 0.5, 1}, {-1, 0.5, 1}}, {0, -1, 0});
  const std::vector<PanelCrossing> c = p.crossings();
  ASSERT_EQ(c.size(), 1u);
  // The deepest point is in one arm (x in (0, 1) or (2, 3)), 0.5 from the U's outline at most.
  const double x = c[0].point.x();
  EXPECT_TRUE((x > 0.0 && x < 1.0) || (x > 2.0 && x < 3.0)) << x;
  EXPECT_GT(c[0].depth, 0.3);
  EXPECT_LE(c[0].depth, 0.5 + 1e-12);
}

TEST(PanelCrossings, ShallowerThanTheToleranceIsNotACrossing) {
  Panels p;
  p.add({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 0, 1});
  // Rises 1e-6 above z = 0 through the square: 5e-7 of the smaller panel's size deep.
  p.add({{-0.5, 0, -2.0}, {-0.5, 0, 1e-6}, {0.5, 0, 1e-6}, {0.5, 0, -2.0}}, {0, 1, 0});
  EXPECT_TRUE(p.crossings().empty());
  // 0.1 above it: a crossing.
  p.vertices[5].z() = p.vertices[6].z() = 0.1;
  EXPECT_EQ(p.crossings().size(), 1u);
}

// The quality report lists them and does not (yet) count them invalid: on cow.off at 70
// panels, seed 1, five pairs where the tail goes into the rump, as the input itself does (83
// pairs of its triangles cross); on the bunny none.
TEST(PanelCrossings, TheReportListsThemOnTheCow) {
  const QualityReport q = solved_quality("cow.off", 70);
  EXPECT_FALSE(q.crossing_pairs.empty());
  EXPECT_EQ(q.crossing_pairs.size(), q.crossing_points.size());
  EXPECT_GT(q.max_crossing_depth, 0.01);
  // The model itself passes through itself there (its tail goes into its rump).
  EXPECT_GT(q.input_crossings, 50);
  EXPECT_LT(q.input_crossing_point.x(), -0.35);
  const QualityReport b = solved_quality("bunny.off", 100);
  EXPECT_TRUE(b.crossing_pairs.empty());
  EXPECT_EQ(b.max_crossing_depth, 0.0);
  EXPECT_EQ(b.input_crossings, 0);
}

// Crossings scattered over a large box at very different sizes, with panels that meet no other
// and one far larger panel that meets none: exactly the crossing pairs, whichever grid cells
// they share (the broad phase takes each overlapping pair once).
TEST(PanelCrossings, EveryCrossingIsFoundOnceWhereverItIs) {
  Panels p;
  std::vector<std::array<int, 2>> expected;
  for (int k = 0; k < 60; ++k) {
    const double size = k % 7 == 0 ? 40.0 : k % 3 == 0 ? 0.05 : 1.0 + 0.1 * k;
    const Vec3 at(100.0 * (k % 5), 37.0 * (k % 4) - 50.0, 13.0 * k);
    const int a = static_cast<int>(p.panels.size());
    if (k % 4 == 3) {  // an L: two panels along one edge, not through each other
      p.add({at, at + Vec3(size, 0, 0), at + Vec3(size, size, 0), at + Vec3(0, size, 0)}, Vec3::UnitZ());
      p.add({at, at + Vec3(0, 0, size), at + Vec3(size, 0, size), at + Vec3(size, 0, 0)}, -Vec3::UnitY());
      continue;
    }
    const double h = 0.5 * size;
    p.add({at + Vec3(-h, -h, 0), at + Vec3(h, -h, 0), at + Vec3(h, h, 0), at + Vec3(-h, h, 0)}, Vec3::UnitZ());
    p.add({at + Vec3(-h, 0, -h), at + Vec3(h, 0, -h), at + Vec3(h, 0, h), at + Vec3(-h, 0, h)}, -Vec3::UnitY());
    expected.push_back({a, a + 1});
  }
  p.add({Vec3(-1000, -1000, -500), Vec3(1000, -1000, -500), Vec3(1000, 1000, -500), Vec3(-1000, 1000, -500)},
        Vec3::UnitZ());
  const std::vector<PanelCrossing> found = p.crossings();
  ASSERT_EQ(found.size(), expected.size());
  for (size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found[k].a, expected[k][0]);
    EXPECT_EQ(found[k].b, expected[k][1]);
  }
}

// A wall across the x axis of 80,000 triangles with one triangle through it: found, and only
// near it. (The check's earlier sweep along x compared every pair of the wall's triangles
// here: 17 s against 0.2 s, measured, not asserted.)
TEST(PanelCrossings, AWallAcrossOneAxisIsCheckedPairByPair) {
  TriMesh wall;
  const int side = 200;
  for (int i = 0; i <= side; ++i) {
    for (int j = 0; j <= side; ++j) wall.positions.emplace_back(0.0, i, j);
  }
  const auto at = [&](int i, int j) { return i * (side + 1) + j; };
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      wall.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      wall.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  const SurfaceCrossings plain = surface_crossings(wall);
  ASSERT_TRUE(plain.checked);
  ASSERT_TRUE(plain.pairs.empty());
  const int v = static_cast<int>(wall.positions.size());
  wall.positions.emplace_back(-0.5, 100.3, 100.2);
  wall.positions.emplace_back(0.5, 100.3, 100.2);
  wall.positions.emplace_back(0.0, 100.3, 100.9);
  wall.triangles.push_back({v, v + 1, v + 2});  // through the wall across one of its cells
  const std::vector<PanelCrossing> found = surface_crossings(wall).pairs;
  ASSERT_FALSE(found.empty());
  for (const PanelCrossing& c : found) {
    EXPECT_EQ(c.b, static_cast<int>(wall.triangles.size()) - 1);
    EXPECT_NEAR(c.point.x(), 0.0, 1e-9);
    EXPECT_NEAR(c.point.y(), 100.3, 1e-9);
  }
}

// The shared meshes: the cow's tail goes into its rump (83 pairs of its triangles cross in 4
// places), the camel's head has a few (5 pairs in one place), the bunny none.
TEST(SurfaceCrossings, TheCowPassesThroughItselfTheBunnyDoesNot) {
  const SurfaceCrossings cow = surface_crossings(test::load_clean("cow.off"));
  EXPECT_EQ(cow.pairs.size(), 83u);
  EXPECT_EQ(cow.places, 4);
  for (const PanelCrossing& c : cow.pairs) EXPECT_LT(c.point.x(), -0.3);  // the tail, at the back
  const SurfaceCrossings camel = surface_crossings(test::load_clean("camelhead.off"));
  EXPECT_EQ(camel.pairs.size(), 5u);
  EXPECT_EQ(camel.places, 1);
  const SurfaceCrossings bunny = surface_crossings(test::load_clean("bunny.off"));
  EXPECT_TRUE(bunny.checked);
  EXPECT_TRUE(bunny.pairs.empty());
  EXPECT_EQ(bunny.places, 0);
}

// Where it crosses, counted as places: a flat grid with small triangles pushed through it at
// separate spots is one place per spot, however many grid triangles each one cuts; two
// triangles pushed through that share a corner are one place, wherever they cut the grid.
TEST(SurfaceCrossings, PlacesCountSeparateSpotsNotPairs) {
  const auto grid = [] {
    TriMesh m;
    const int n = 20;  // 20 x 20 cells of 1 x 1 in z = 0
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.positions.emplace_back(i, j, 0.0);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int v = j * (n + 1) + i;
        m.triangles.push_back({v, v + 1, v + n + 2});
        m.triangles.push_back({v, v + n + 2, v + n + 1});
      }
    }
    return m;
  };
  // A vertical triangle through the grid at (x, y), 3 cells wide along x.
  const auto poke = [](TriMesh& m, double x, double y) {
    const int v = static_cast<int>(m.positions.size());
    m.positions.emplace_back(x - 1.5, y, -1.0);
    m.positions.emplace_back(x + 1.5, y, -1.0);
    m.positions.emplace_back(x, y, 1.0);
    m.triangles.push_back({v, v + 1, v + 2});
  };
  TriMesh one = grid();
  poke(one, 5.3, 5.6);
  const SurfaceCrossings at_one = surface_crossings(one);
  EXPECT_GT(at_one.pairs.size(), 2u);
  EXPECT_EQ(at_one.places, 1);

  TriMesh three = grid();
  poke(three, 5.3, 5.6), poke(three, 14.3, 5.6), poke(three, 10.3, 15.6);
  const SurfaceCrossings at_three = surface_crossings(three);
  EXPECT_EQ(at_three.places, 3) << at_three.pairs.size() << " pairs";

  // A second triangle from the first one's top corner, slanting down through the grid at x =
  // 9.3, three cells from where the first cuts it (x 4.55-6.05): the grid triangles the two cut
  // share no corner, so only their shared top corner joins them, into one place. The same
  // triangle with a corner of its own at that point is a second place.
  for (const bool shared : {true, false}) {
    TriMesh slanted = grid();
    poke(slanted, 5.3, 5.6);
    int top = static_cast<int>(slanted.positions.size()) - 1;
    if (!shared) {
      slanted.positions.push_back(slanted.positions.back());
      top += 1;
    }
    const int v = static_cast<int>(slanted.positions.size());
    slanted.positions.emplace_back(13.3, 5.3, -1.0);
    slanted.positions.emplace_back(13.3, 5.9, -1.0);
    slanted.triangles.push_back({v, v + 1, top});
    const SurfaceCrossings found = surface_crossings(slanted);
    EXPECT_EQ(found.places, shared ? 1 : 2)
        << (shared ? "shared" : "own") << " corner, " << found.pairs.size() << " pairs";
  }

  EXPECT_EQ(surface_crossings(grid()).places, 0);
}

// Tall thin strips side by side (a wall of 40,000 triangles 10 high and 0.005 wide, and a
// cylinder's ring of them): each cell is sized along each axis, so the strips are compared
// with their neighbours only (cells sized by the largest extent held every strip in one: 9 s
// for 100,000; measured, not asserted). A triangle pushed through one strip is found.
TEST(SurfaceCrossings, TallThinStripsAreComparedWithTheirNeighbours) {
  const int n = 20000;
  const double through = 2 * M_PI * (5000.5 / n);  // the middle of strip 5000
  for (const bool ring : {false, true}) {
    TriMesh strips;
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      const Vec3 foot =
          ring ? Vec3(20.0 * std::cos(2 * M_PI * t), 0.0, 20.0 * std::sin(2 * M_PI * t)) : Vec3(100.0 * t, 0.0, 0.0);
      strips.positions.push_back(foot);
      strips.positions.push_back(foot + Vec3(0.0, 10.0, 0.0));
    }
    for (int i = 0; i < n; ++i) {
      if (ring && i == n - 1) break;  // no closing seam: the first and last strips would overlap
      strips.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
      strips.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    const SurfaceCrossings plain = surface_crossings(strips);
    EXPECT_TRUE(plain.checked);
    EXPECT_TRUE(plain.pairs.empty());
    const Vec3 across = ring ? Vec3(std::cos(through), 0.0, std::sin(through)) : Vec3::UnitZ();
    const Vec3 along = ring ? Vec3(-std::sin(through), 0.0, std::cos(through)) : Vec3::UnitX();
    const Vec3 at = (ring ? 20.0 * across : Vec3(100.0 * 5000.5 / n, 0.0, 0.0)) + Vec3(0.0, 5.0, 0.0);
    const int v = static_cast<int>(strips.positions.size());
    strips.positions.push_back(at - 0.5 * across - 0.0003 * along);
    strips.positions.push_back(at + 0.5 * across + 0.0003 * along);
    strips.positions.push_back(at + Vec3(0.0, 0.5, 0.0));
    strips.triangles.push_back({v, v + 1, v + 2});
    const SurfaceCrossings found = surface_crossings(strips);
    EXPECT_TRUE(found.checked);
    ASSERT_FALSE(found.pairs.empty()) << (ring ? "ring" : "wall");
    for (const PanelCrossing& c : found.pairs) EXPECT_EQ(c.b, static_cast<int>(strips.triangles.size()) - 1);
  }
}

// A disc as a fan of 100,000 long thin triangles around its centre: every box holds the
// centre, so every pair of boxes overlaps (5e9 tests, minutes). The check says it did not look
// rather than take that long; a fan of 1,000 is checked.
TEST(SurfaceCrossings, AFanTooLargeToCheckSaysSo) {
  for (const int n : {1000, 100000}) {
    TriMesh fan;
    fan.positions.emplace_back(0.0, 0.0, 0.0);
    for (int i = 0; i < n; ++i) fan.positions.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.0);
    for (int i = 0; i < n; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
    const SurfaceCrossings found = surface_crossings(fan);
    EXPECT_EQ(found.checked, n == 1000) << n;
    EXPECT_TRUE(found.pairs.empty());
  }
}

// The report checks the input whether or not panels cross: camelhead.off's 5 pairs are too
// small to show in its 60 panels, and the report still says the model crosses itself (before,
// input_crossings was looked at only when panels crossed, and a 0 could mean "not looked").
TEST(SurfaceCrossings, TheReportChecksTheInputEvenWhereNoPanelsCross) {
  const QualityReport q = solved_quality("camelhead.off", 60);
  EXPECT_TRUE(q.crossing_pairs.empty());
  EXPECT_EQ(q.input_crossings, 5);
  EXPECT_NE(q.input_crossing_point, Vec3::Zero());
}

// A caller that checked the mesh as it opened (the CLI, the page) gives its crossings to the
// report, which takes them as they are: the same report as when it checks the mesh itself.
TEST(SurfaceCrossings, TheReportTakesTheCrossingsItIsGiven) {
  RemeshParams params;
  params.panels = 60;
  const TriMesh loaded = test::load_clean("camelhead.off");
  Remesher remesher(loaded, params);
  remesher.run();
  QualityOptions given;
  given.input_crossings = surface_crossings(loaded);  // as the CLI has it: the mesh it loaded
  ASSERT_EQ(given.input_crossings->pairs.size(), 5u);
  EXPECT_EQ(surface_crossings(remesher.mesh()).pairs.front().point, given.input_crossings->pairs.front().point);
  const QualityReport own = measure_quality(remesher.mesh(), remesher.topology(), remesher.panels());
  const QualityReport taken = measure_quality(remesher.mesh(), remesher.topology(), remesher.panels(), given);
  EXPECT_EQ(taken.input_crossings, own.input_crossings);
  EXPECT_EQ(taken.input_crossing_point, own.input_crossing_point);
  EXPECT_EQ(taken.input_crossing_places, 1);
  EXPECT_EQ(taken.input_crossing_places, own.input_crossing_places);
  // Taken, not checked again: an unchecked surface is said as such (-1), one pair as one.
  given.input_crossings->checked = false;
  const QualityReport unchecked = measure_quality(remesher.mesh(), remesher.topology(), remesher.panels(), given);
  EXPECT_EQ(unchecked.input_crossings, -1);
  EXPECT_EQ(unchecked.input_crossing_places, 0);
  given.input_crossings->checked = true;
  given.input_crossings->pairs.resize(1);
  EXPECT_EQ(measure_quality(remesher.mesh(), remesher.topology(), remesher.panels(), given).input_crossings, 1);
}

// What the CLI's warning and the report's Crossing hint say of where.
TEST(SurfaceCrossings, WhereIsSaidWithItsPlaces) {
  const Vec3 p(-0.42, 0.219, -0.00695);
  EXPECT_EQ(crossing_where(4, p), "in 4 places, one near (-0.42, 0.219, -0.00695)");
  EXPECT_EQ(crossing_where(1, p), "in one place, near (-0.42, 0.219, -0.00695)");
  EXPECT_EQ(crossing_where(0, p), "near (-0.42, 0.219, -0.00695)");
}

}  // namespace
}  // namespace ff
