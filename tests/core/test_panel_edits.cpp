// Per-panel edits (issue 6, paper 6): split adds a panel, merge removes one, both keep every
// invariant of the planar panels (panel_checks.h); a locked panel keeps its faces, its plane
// and its outline through re-solves at other counts and weights; edit lists replay to the
// same bytes; bad edits throw InputError and leave the design as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "cluster_checks.h"
#include "core/cluster/cluster_edits.h"
#include "core/panels/panel_export.h"
#include "core/remesh_params_json.h"
#include "core/shapes/hard_cases.h"
#include "core/util/error.h"
#include "panel_checks.h"

namespace ff {
namespace {

struct EditCase {
  std::string name;
  int panels;
};

void PrintTo(const EditCase& c, std::ostream* os) { *os << c.name << " at " << c.panels; }

TriMesh case_mesh(const std::string& name) {
  if (name.find('.') != std::string::npos) return test::load_clean(name);
  for (NamedShape& s : hard_cases(8000)) {
    if (s.name == name) return std::move(s.mesh);
  }
  ADD_FAILURE() << "no hard case " << name;
  return {};
}

std::string obj(const Remesher& r) { return panels_obj(r.panels(), "edits test"); }

int face_count(const Remesher& r, int cluster) {
  const std::vector<int>& l = r.clustering().labels;
  return static_cast<int>(std::count(l.begin(), l.end(), cluster));
}

// The seed face of the largest cluster: a panel worth splitting.
int big_panel_face(const Remesher& r) {
  int best = 0;
  for (int c = 1; c < r.num_panels(); ++c) {
    if (face_count(r, c) > face_count(r, best)) best = c;
  }
  return r.clustering().seeds[static_cast<size_t>(best)];
}

// Two faces on neighbouring panels (across an edge), from the middle of the face list.
std::pair<int, int> neighbour_faces(const Remesher& r) {
  const std::vector<int>& l = r.clustering().labels;
  for (size_t k = 0; k < l.size(); ++k) {
    const size_t f = (k + l.size() / 2) % l.size();
    for (int g : r.topology().face_neighbors[f]) {
      if (g >= 0 && l[static_cast<size_t>(g)] != l[f]) return {static_cast<int>(f), g};
    }
  }
  return {-1, -1};
}

// Two faces on panels that share no edge.
std::pair<int, int> distant_faces(const Remesher& r) {
  const std::vector<int>& l = r.clustering().labels;
  for (int f = 0; f < static_cast<int>(l.size()); ++f) {
    const int c = l[static_cast<size_t>(f)], d = l[0];
    if (c != d && !clusters_share_edge(r.topology(), l, d, c)) return {0, f};
  }
  return {-1, -1};
}

// A face on a panel away from the panel at `face` (not it, not around it).
int face_away_from(const Remesher& r, int face) {
  const std::vector<int>& l = r.clustering().labels;
  const int c = l[static_cast<size_t>(face)];
  std::vector<int> near = cluster_ring(r.mesh(), r.topology(), l, c);
  near.push_back(c);
  for (size_t k = 0; k < l.size(); ++k) {
    const size_t f = (k + l.size() / 3) % l.size();
    const std::vector<int> ring = cluster_ring(r.mesh(), r.topology(), l, l[f]);
    if (std::find(near.begin(), near.end(), l[f]) == near.end() &&
        std::find_first_of(ring.begin(), ring.end(), near.begin(), near.end()) == ring.end())
      return static_cast<int>(f);
  }
  return -1;
}

double model_size(const Remesher& r) {
  Vec3 lo = r.mesh().positions[0], hi = lo;
  for (const Vec3& p : r.mesh().positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

// A locked panel as the design shows it: its faces, plane and polygon.
struct PanelShot {
  std::vector<int> faces;
  Vec3 normal;
  double offset = 0.0;
  std::vector<Vec3> polygon;
};

PanelShot shot(const Remesher& r, int face) {
  PanelShot s;
  const int c = r.clustering().labels[static_cast<size_t>(face)];
  for (size_t f = 0; f < r.clustering().labels.size(); ++f) {
    if (r.clustering().labels[f] == c) s.faces.push_back(static_cast<int>(f));
  }
  const PanelMesh& pm = r.panels();
  for (int p = 0; p < pm.num_panels(); ++p) {
    if (pm.panel_cluster[static_cast<size_t>(p)] != c) continue;
    s.normal = pm.plane_normals[static_cast<size_t>(p)];
    s.offset = pm.plane_offsets[static_cast<size_t>(p)];
    for (int v : pm.panels[static_cast<size_t>(p)]) s.polygon.push_back(pm.vertices[static_cast<size_t>(v)]);
  }
  return s;
}

// Same faces and plane exactly; the same polygon within `tol` (it may start at another vertex:
// which corner a polygon starts from follows the node groups, which move with the count).
::testing::AssertionResult same_panel(const PanelShot& a, const PanelShot& b, double tol) {
  if (a.faces != b.faces) return ::testing::AssertionFailure() << "faces differ";
  if (a.normal != b.normal || a.offset != b.offset)
    return ::testing::AssertionFailure() << "plane differs by " << (a.normal - b.normal).norm() << ", "
                                         << a.offset - b.offset;
  if (a.polygon.size() != b.polygon.size() || a.polygon.empty())
    return ::testing::AssertionFailure() << a.polygon.size() << " vs " << b.polygon.size() << " vertices";
  const size_t n = a.polygon.size();
  size_t shift = 0;
  for (size_t k = 1; k < n; ++k) {
    if ((b.polygon[k] - a.polygon[0]).norm() < (b.polygon[shift] - a.polygon[0]).norm()) shift = k;
  }
  double worst = 0.0;
  for (size_t k = 0; k < n; ++k) worst = std::max(worst, (a.polygon[k] - b.polygon[(k + shift) % n]).norm());
  if (!(worst <= tol)) return ::testing::AssertionFailure() << "a vertex moved by " << worst;
  return ::testing::AssertionSuccess() << "vertices within " << worst;
}

PanelEdit edit(PanelEdit::Op op, int face, int with = -1) { return PanelEdit{op, face, with}; }

class PanelEdits : public ::testing::TestWithParam<EditCase> {};

// The case solved at its panel count (a Remesher cannot move: held by pointer).
std::unique_ptr<Remesher> solve_case(const EditCase& c) {
  RemeshParams p;
  p.panels = c.panels;
  auto r = std::make_unique<Remesher>(case_mesh(c.name), p);
  r->run();
  return r;
}

TEST_P(PanelEdits, SplitAddsAPanelMergeRemovesOne) {
  const EditCase& c = GetParam();
  const std::unique_ptr<Remesher> solved = solve_case(c);
  Remesher& r = *solved;
  ASSERT_TRUE(test::valid_panels(r, c.panels, 0.08));
  const int split = big_panel_face(r);
  r.set_edits({edit(PanelEdit::Op::Split, split)});
  EXPECT_EQ(r.num_panels(), c.panels + 1);
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), r.clustering().labels, r.num_panels()));
  EXPECT_TRUE(test::valid_panels(r, c.panels + 1, 0.08)) << "after split";
  const auto [a, b] = neighbour_faces(r);
  ASSERT_GE(a, 0);
  r.set_edits({edit(PanelEdit::Op::Split, split), edit(PanelEdit::Op::Merge, a, b)});
  EXPECT_EQ(r.num_panels(), c.panels);
  EXPECT_EQ(r.clustering().labels[static_cast<size_t>(a)], r.clustering().labels[static_cast<size_t>(b)]);
  EXPECT_TRUE(test::valid_panels(r, c.panels, 0.08)) << "after merge";
}

// The invalid panels of a design, one per line with their problems (empty when none).
std::string invalid_panels(const Remesher& r) {
  const PanelMesh& pm = r.panels();
  const std::vector<int> locked = r.locked_clusters();
  std::string out;
  for (int p = 0; p < pm.num_panels(); ++p) {
    const PanelIssues& i = pm.issues[static_cast<size_t>(p)];
    if (i.valid()) continue;
    const int c = pm.panel_cluster[static_cast<size_t>(p)];
    out += "\n  panel " + std::to_string(p) + " (cluster " + std::to_string(c) +
           (std::find(locked.begin(), locked.end(), c) != locked.end() ? ", locked" : "") + "): spikes " +
           std::to_string(i.spike_vertices) + (i.flipped ? ", flipped" : "") + (i.not_star ? ", not star" : "") +
           (i.not_simple ? ", not simple" : "") + (i.not_disk ? ", not a disk" : "");
  }
  for (int c : pm.unbuilt_clusters) out += "\n  cluster " + std::to_string(c) + " unbuilt";
  return out;
}

// A lock holds the panel's faces and plane, its neighbours' planes (each may only turn about
// its edge line with the locked panel) and its node pairings: its outline stays exactly, with
// the same vertices, through re-solves at +-20% and +-10% panels and new weights; and the
// design around it is as valid as without the lock: no invalid panel at all (the locked
// panel's vertices are judged by the spike distance it was locked with).
class PanelLocks : public PanelEdits {};
TEST_P(PanelLocks, LockedPanelSurvivesReSolves) {
  const EditCase& c = GetParam();
  const std::unique_ptr<Remesher> solved = solve_case(c);
  Remesher& r = *solved;
  const int face = big_panel_face(r);
  r.set_edits({edit(PanelEdit::Op::Lock, face)});
  const PanelShot locked = shot(r, face);
  ASSERT_EQ(r.locked_clusters(), std::vector<int>{r.clustering().labels[static_cast<size_t>(face)]});
  ASSERT_EQ(r.panels().num_invalid(), 0) << invalid_panels(r);
  const double tol = 1e-9 * model_size(r);
  const int counts[] = {c.panels * 6 / 5, c.panels * 4 / 5, c.panels * 11 / 10, c.panels * 9 / 10, c.panels};
  for (int step = 0; step < 5; ++step) {
    RemeshParams q = r.params();
    q.panels = counts[step];
    if (step == 4) q.weights.l21 = 0.5, q.weights.euclidean = 2.0;
    r.set_params(q);
    r.run();
    EXPECT_EQ(r.num_panels(), q.panels) << "step " << step;
    EXPECT_TRUE(same_panel(locked, shot(r, face), tol)) << "step " << step;
    const QualityReport quality = measure_quality(r.mesh(), r.topology(), r.panels());
    EXPECT_LE(quality.max_planarity, 1e-9);
    EXPECT_TRUE(quality.topology_preserved && quality.oriented_manifold) << "step " << step;
    EXPECT_EQ(r.panels().num_invalid(), 0) << "step " << step << ", " << q.panels << " panels:" << invalid_panels(r);
    EXPECT_EQ(quality.invalid_panels, 0) << "step " << step << " (quality check), spikes " << quality.spike_vertices;
    ASSERT_EQ(r.locked_clusters().size(), 1u);
  }
}

// Clusters whose panel shares a vertex with a panel of a cluster its faces do not touch:
// where four clusters meet at a mesh corner, the node pairing gives two of them that touch
// only there (or not even there, once the corner is cut) a short edge of their own.
std::vector<int> panels_with_a_node_only_neighbour(const Remesher& r) {
  const PanelMesh& pm = r.panels();
  std::vector<std::vector<int>> clusters_at(pm.vertices.size());
  for (int p = 0; p < pm.num_panels(); ++p) {
    for (int v : pm.panels[static_cast<size_t>(p)])
      clusters_at[static_cast<size_t>(v)].push_back(pm.panel_cluster[static_cast<size_t>(p)]);
  }
  std::vector<int> out;
  for (int p = 0; p < pm.num_panels(); ++p) {
    const int c = pm.panel_cluster[static_cast<size_t>(p)];
    const std::vector<int> ring = cluster_ring(r.mesh(), r.topology(), r.clustering().labels, c);
    bool found = false;
    for (int v : pm.panels[static_cast<size_t>(p)]) {
      for (int d : clusters_at[static_cast<size_t>(v)])
        found = found || (d != c && !std::binary_search(ring.begin(), ring.end(), d));
    }
    if (found) out.push_back(c);
  }
  return out;
}

// A lock holds every plane that makes a corner of the panel, also the plane of a cluster its
// faces do not touch (above): an edit far away re-solves the design, and that plane was
// refitted with the rest (the outline moved by up to 67 units on the hyperboloid, a panel 90
// across, and the run ended valid).
TEST_P(PanelLocks, LockHoldsPlanesThatMeetItOnlyAtANode) {
  const EditCase& c = GetParam();
  const std::unique_ptr<Remesher> solved = solve_case(c);
  Remesher& r = *solved;
  const std::vector<int> candidates = panels_with_a_node_only_neighbour(r);
  ASSERT_FALSE(candidates.empty()) << "no panel with a node-only neighbour: the case tests nothing";
  for (size_t k = 0; k < candidates.size() && k < 3; ++k) {
    const int face = r.clustering().seeds[static_cast<size_t>(candidates[k * candidates.size() / 3])];
    r.set_edits({edit(PanelEdit::Op::Lock, face)});
    const PanelShot locked = shot(r, face);
    const int far = face_away_from(r, face);
    ASSERT_GE(far, 0);
    r.set_edits({edit(PanelEdit::Op::Lock, face), edit(PanelEdit::Op::Split, far)});
    EXPECT_EQ(r.num_panels(), c.panels + 1);
    EXPECT_TRUE(same_panel(locked, shot(r, face), 1e-9 * model_size(r))) << "panel at face " << face;
    r.set_edits({});
  }
}

// With single-point nodes the finish pins groups of four or more planes through one point,
// which moved locked planes and their neighbours' (bunny.off at 100 panels, seed 2: the
// locked outline went from 6 vertices to 4 after a merge far away, exit 0; found by an audit
// of the locks). Planes held by a lock stay, and so do the groups whose pairing a lock holds.
TEST(PanelLockHolds, ThroughSinglePointNodes) {
  const TriMesh bunny = test::load_clean("bunny.off");
  // The audit's cases: a merge far away at seed 2, a split at seed 1.
  for (const auto& [seed, far] : {std::make_pair(2u, edit(PanelEdit::Op::Merge, 2702, 3655)),
                                  std::make_pair(1u, edit(PanelEdit::Op::Split, 2702))}) {
    RemeshParams p;
    p.panels = 100;
    p.seed = seed;
    p.single_point_nodes = true;
    Remesher r(bunny, p);
    r.run();
    r.set_edits({edit(PanelEdit::Op::Lock, 2089)});
    const PanelShot locked = shot(r, 2089);
    r.set_edits({edit(PanelEdit::Op::Lock, 2089), far});
    EXPECT_TRUE(same_panel(locked, shot(r, 2089), 1e-9 * model_size(r))) << "seed " << seed;
    EXPECT_EQ(r.panels().num_invalid(), 0) << "seed " << seed << invalid_panels(r);
  }
}

// Locks hold their panels and neighbours: a count below what they hold (plus one panel for
// each part of the surface they leave free) is refused by name, the design left as it was.
// Before, three locks on the bunny and 10 panels gave 16 clusters, 8 of them unbuilt.
TEST(PanelLockHolds, TooFewPanelsForTheLocksIsRefused) {
  RemeshParams p;
  p.panels = 100;
  Remesher r(test::load_clean("bunny.off"), p);
  r.run();
  r.set_edits({edit(PanelEdit::Op::Lock, 2089), edit(PanelEdit::Op::Lock, 303), edit(PanelEdit::Op::Lock, 25)});
  const std::string before = obj(r);
  RemeshParams q = r.params();
  q.panels = 10;
  try {
    r.set_params(q);
    ADD_FAILURE() << "10 panels with three locks accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("10 panels cannot keep the 3 locked panels"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ask for at least"), std::string::npos) << e.what();
  }
  EXPECT_EQ(obj(r), before);
  EXPECT_EQ(r.params().panels, 100);
  // The least it names is reached, every panel built.
  q.panels = 60;
  r.set_params(q);
  r.run();
  EXPECT_EQ(r.num_panels(), 60);
  EXPECT_TRUE(r.panels().unbuilt_clusters.empty());
}

// Which corners make one node group follows the spike distance, which moves with the panel
// count and the weights: a re-solve regrouped a locked panel's corners and its outline lost
// a vertex, the run valid (3holes.off at 100 panels, seed 1, then 110: 7 vertices to 6; the
// hyperboloid at 100, seed 2, then 200: 8 to 7; found by an audit of the locks). The lock holds
// its corners' grouping. Over five shared meshes at 100 panels, seeds 1-3, three locks each,
// then 110, 120, 200 panels or no L2 term: 180 of 180 outlines kept (3 moved before).
TEST(PanelLockHolds, ThroughAReSolveThatWouldRegroupItsCorners) {
  struct Case {
    const char* mesh;
    unsigned seed;
    int face, panels_after;
  };
  for (const Case& c : {Case{"3holes.off", 1, 2160, 110}, Case{"hyperboloid_s4.off", 2, 15136, 200}}) {
    RemeshParams p;
    p.panels = 100;
    p.seed = c.seed;
    Remesher r(test::load_clean(c.mesh), p);
    r.run();
    r.set_edits({edit(PanelEdit::Op::Lock, c.face)});
    const PanelShot locked = shot(r, c.face);
    RemeshParams q = r.params();
    q.panels = c.panels_after;
    r.set_params(q);
    r.run();
    EXPECT_TRUE(same_panel(locked, shot(r, c.face), 1e-9 * model_size(r))) << c.mesh;
    EXPECT_EQ(r.panels().num_invalid(), 0) << c.mesh << invalid_panels(r);
  }
}

// A split or merge a lock stands in the way of names the lock (before: "locked or next to a
// locked panel", whichever it was and whichever lock).
TEST(PanelLockHolds, ARefusedEditNamesTheLockInTheWay) {
  RemeshParams p;
  p.panels = 69;
  Remesher r(test::load_clean("bunny.off"), p);
  r.run();
  const int lock = big_panel_face(r);
  const int locked = r.clustering().labels[static_cast<size_t>(lock)];
  const std::vector<int> ring = cluster_ring(r.mesh(), r.topology(), r.clustering().labels, locked);
  ASSERT_FALSE(ring.empty());
  const int next_to = r.clustering().seeds[static_cast<size_t>(ring.front())];
  const auto refusal = [&](int face) {
    try {
      r.set_edits({edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Split, face)});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(lock), "edit 2 (split): the panel at face " + std::to_string(lock) + " is locked: unlock it first");
  EXPECT_EQ(refusal(next_to), "edit 2 (split): the panel at face " + std::to_string(next_to) +
                                  " is next to the panel locked at face " + std::to_string(lock) +
                                  ": unlock that first");
}

const auto case_name = [](const auto& info) {
  return test::test_name(info.param.name) + "_" + std::to_string(info.param.panels);
};

INSTANTIATE_TEST_SUITE_P(Cases, PanelEdits,
                         ::testing::Values(EditCase{"inspired_mesh.obj", 42}, EditCase{"bunny.off", 69},
                                           EditCase{"saddle", 60}, EditCase{"barrel_vault", 60}),
                         case_name);
// The dense hyperboloid takes about a minute (five re-solves of 50k triangles).
INSTANTIATE_TEST_SUITE_P(Cases, PanelLocks,
                         ::testing::Values(EditCase{"inspired_mesh.obj", 42}, EditCase{"bunny.off", 69},
                                           EditCase{"saddle", 60}, EditCase{"barrel_vault", 60},
                                           EditCase{"Moomoo.off", 77}, EditCase{"hyperboloid_s4.off", 300}),
                         case_name);

// The dense case for split and merge (its lock round trip is in PanelLocks).
INSTANTIATE_TEST_SUITE_P(Dense, PanelEdits, ::testing::Values(EditCase{"hyperboloid_s4.off", 300}), case_name);

TEST(PanelEditLists, ReplayToTheSameBytes) {
  const TriMesh mesh = test::load_clean("inspired_mesh.obj");
  RemeshParams p;
  p.panels = 42;
  Remesher live(mesh, p);
  live.run();
  const int split = big_panel_face(live);
  const int lock = face_away_from(live, split);
  ASSERT_GE(lock, 0);
  std::vector<PanelEdit> edits{edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Split, split)};
  // Applied one at a time, as a designer clicks; then the whole list on a fresh solve.
  live.set_edits({edits[0]});
  live.set_edits(edits);
  p.edits = edits;
  Remesher replay(mesh, p);
  replay.run();
  Remesher again(mesh, p);
  again.run();
  EXPECT_EQ(obj(replay), obj(again));
  EXPECT_EQ(obj(live), obj(replay));
  // Undo and redo: the shorter list gives what that list gives from scratch.
  const std::string both = obj(live);
  live.set_edits({edits[0]});
  RemeshParams one = p;
  one.edits = {edits[0]};
  Remesher first(mesh, one);
  first.run();
  EXPECT_EQ(obj(live), obj(first));
  live.set_edits(edits);
  EXPECT_EQ(obj(live), both);
  EXPECT_EQ(live.num_panels(), 43);
}

// After a split the page shows the count now (43 from 42): that count, or the target, sent
// back with the same edits is no change: no re-solve, the very same panels, the target kept,
// and undo still gives what the shorter list gives. A new count still re-solves.
TEST(PanelEditLists, CountNowIsNoChange) {
  const TriMesh mesh = test::load_clean("inspired_mesh.obj");
  RemeshParams p;
  p.panels = 42;
  Remesher r(mesh, p);
  r.run();
  const std::string before = obj(r);
  const std::vector<PanelEdit> edits{edit(PanelEdit::Op::Split, big_panel_face(r))};
  r.set_edits(edits);
  ASSERT_EQ(r.num_panels(), 43);
  const std::string split = obj(r);
  for (int count : {43, 42}) {
    RemeshParams q = r.params();
    q.panels = count;
    EXPECT_TRUE(r.kept_count(q)) << count;
    r.set_params(q);
    EXPECT_TRUE(r.done()) << count << ": solving again";
    EXPECT_EQ(r.params().panels, 42) << count;
    EXPECT_EQ(r.num_panels(), 43) << count;
    EXPECT_EQ(obj(r), split) << count;
  }
  // Undo and redo replay from the design before the split, as without the calls above.
  r.set_edits({});
  EXPECT_EQ(obj(r), before);
  r.set_edits(edits);
  EXPECT_EQ(obj(r), split);
  // Other parameters with the count now: a re-solve that keeps 43 panels (not back to 42).
  RemeshParams w = r.params();
  w.panels = 43;
  w.weights.l21 = 0.5;
  r.set_params(w);
  EXPECT_FALSE(r.done());
  r.run();
  EXPECT_EQ(r.num_panels(), 43);
  EXPECT_EQ(r.params().panels, 42);
  EXPECT_TRUE(test::valid_panels(r, 43, 0.08));
  // A new count is one: 50 panels reached from the design.
  RemeshParams n = r.params();
  n.panels = 50;
  EXPECT_FALSE(r.kept_count(n));
  r.set_params(n);
  r.run();
  EXPECT_EQ(r.num_panels(), 50);
  EXPECT_EQ(r.params().panels, 50);
  // Without edits the count is what it always was: the same parameters solve again.
  Remesher plain(mesh, p);
  plain.run();
  EXPECT_FALSE(plain.kept_count(p));
  plain.set_params(p);
  EXPECT_FALSE(plain.done());
}

TEST(PanelEditLists, BadEditsThrowAndKeepTheDesign) {
  RemeshParams p;
  p.panels = 42;
  Remesher r(test::load_clean("inspired_mesh.obj"), p);
  r.run();
  const int faces = r.mesh().num_faces();
  const int lock = big_panel_face(r);
  r.set_edits({edit(PanelEdit::Op::Lock, lock)});
  const std::string before = obj(r);
  const std::vector<int> labels = r.clustering().labels;
  const auto [d0, d1] = distant_faces(r);
  ASSERT_GE(d0, 0);
  const std::vector<std::vector<PanelEdit>> bad = {
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Split, faces)},
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Lock, -1)},
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Merge, d0, d1)},
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Merge, lock, lock)},
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Split, lock)},
      {edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Unlock, d1 == lock ? d0 : d1)},
      {edit(PanelEdit::Op::Unlock, lock), edit(PanelEdit::Op::Unlock, lock)},
  };
  for (size_t k = 0; k < bad.size(); ++k) {
    EXPECT_THROW(r.set_edits(bad[k]), InputError) << "bad list " << k;
    EXPECT_EQ(obj(r), before) << "bad list " << k;
    EXPECT_EQ(r.clustering().labels, labels) << "bad list " << k;
    EXPECT_EQ(r.params().edits.size(), 1u);
    EXPECT_EQ(r.locked_clusters().size(), 1u);
  }
  // Out of range is refused up front, also by the constructor.
  RemeshParams q = p;
  q.edits = {edit(PanelEdit::Op::Split, faces + 5)};
  EXPECT_THROW(Remesher(r.mesh(), q), InputError);
  // After all that, a good edit still works.
  r.set_edits({edit(PanelEdit::Op::Lock, lock), edit(PanelEdit::Op::Unlock, lock)});
  EXPECT_TRUE(r.locked_clusters().empty());
}

TEST(PanelEditsJson, ReadsTheContractStrictly) {
  const RemeshParams p = remesh_params_from_json(
      R"({"panels": 40, "edits": [{"op":"split","face":12}, {"op":"merge","face":3,"with":40},
          {"op":"lock","face":7}, {"op":"unlock","face":7}]})");
  ASSERT_EQ(p.edits.size(), 4u);
  EXPECT_TRUE(p.edits[0] == edit(PanelEdit::Op::Split, 12));
  EXPECT_TRUE(p.edits[1] == edit(PanelEdit::Op::Merge, 3, 40));
  EXPECT_TRUE(p.edits[2] == edit(PanelEdit::Op::Lock, 7));
  EXPECT_TRUE(p.edits[3] == edit(PanelEdit::Op::Unlock, 7));
  EXPECT_EQ(panel_edits_from_json(R"([{"op":"lock","face":0}])").size(), 1u);
  for (const char* bad : {R"({"edits": {}})", R"({"edits": [{"op":"split"}]})", R"({"edits": [{"op":"cut","face":1}]})",
                          R"({"edits": [{"op":"split","face":-1}]})", R"({"edits": [{"op":"split","face":1.5}]})",
                          R"({"edits": [{"op":"merge","face":1}]})", R"({"edits": [{"op":"lock","face":1,"with":2}]})",
                          R"({"edits": [{"op":"lock","face":1,"color":2}]})", R"({"edits": [3]})"}) {
    EXPECT_THROW(remesh_params_from_json(bad), InputError) << bad;
  }
  // At most kMaxEdits.
  std::string many = "[";
  for (int i = 0; i <= kMaxEdits; ++i) many += std::string(i ? "," : "") + R"({"op":"lock","face":1})";
  EXPECT_THROW(panel_edits_from_json(many + "]"), InputError);
  many.erase(many.rfind(",{"));
  EXPECT_EQ(panel_edits_from_json(many + "]").size(), static_cast<size_t>(kMaxEdits));
}

TEST(ClusterEdits, SplitAndMergeKeepTheInvariants) {
  RemeshParams p;
  p.panels = 20;
  p.make_panels = false;
  Remesher r(test::load_clean("bunny.off"), p);
  r.run();
  Clustering c = r.clustering();
  const int added = split_cluster(r.metric(), r.topology(), c, 3);
  ASSERT_EQ(added, 20);
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), c.labels, 21));
  EXPECT_EQ(c.labels[static_cast<size_t>(c.seeds[3])], 3);
  EXPECT_EQ(c.labels[static_cast<size_t>(c.seeds[20])], 20);
  // The two halves are exactly the old cluster.
  for (size_t f = 0; f < c.labels.size(); ++f) {
    const bool was = r.clustering().labels[f] == 3, is = c.labels[f] == 3 || c.labels[f] == 20;
    EXPECT_EQ(was, is) << f;
  }
  ASSERT_TRUE(clusters_share_edge(r.topology(), c.labels, 3, 20));
  const int merged = merge_clusters(r.metric(), c, 3, 20);
  EXPECT_EQ(merged, 3);
  EXPECT_EQ(c.labels, r.clustering().labels);
  const std::vector<int> ring = cluster_ring(r.mesh(), r.topology(), c.labels, 3);
  EXPECT_GE(ring.size(), 3u);
  EXPECT_TRUE(std::find(ring.begin(), ring.end(), 3) == ring.end());
}

}  // namespace
}  // namespace ff
