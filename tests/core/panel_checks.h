#pragma once
// What every panel mesh the remesher returns must be (DESIGN.md 5, issue 3): exactly planar,
// the input's topology as an oriented 2-manifold polygon mesh, no flipped / non-star /
// non-simple / spike / misoriented panel, as many panels as asked, close to the surface.
// Checked by the independent quality module, not by the panel phase's own flags alone.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "core/quality/report.h"
#include "core/remesher.h"
#include "test_meshes.h"

namespace ff::test {

inline ::testing::AssertionResult valid_panels(const Remesher& r, int panels, double max_hausdorff) {
  const PanelMesh& pm = r.panels();
  const QualityReport q = measure_quality(r.mesh(), r.topology(), pm);
  ::testing::AssertionResult fail = ::testing::AssertionFailure();
  fail << pm.num_panels() << " panels, " << pm.num_invalid() << " invalid by the panel phase, " << q.invalid_panels
       << " by the quality check (flipped edges " << q.flipped_edges << ", non-star " << q.non_star_panels
       << ", non-simple " << q.non_simple_panels << ", spikes " << q.spike_vertices << ", misoriented "
       << q.misoriented_panels << "), planarity " << q.max_planarity << ", hausdorff " << q.hausdorff << ", topology "
       << (q.topology_preserved ? "kept" : "broken") << " (euler " << q.euler_in << " -> " << q.euler_out << ", loops "
       << q.boundary_loops_in << " -> " << q.boundary_loops_out << ")";
  if (pm.num_panels() != panels || pm.num_invalid() != 0 || q.invalid_panels != 0) return fail;
  if (!(q.max_planarity <= 1e-9) || !q.topology_preserved || !q.oriented_manifold) return fail;
  if (q.flipped_edges != 0 || q.non_star_panels != 0 || q.non_simple_panels != 0 || q.spike_vertices != 0 ||
      q.misoriented_panels != 0)
    return fail;
  if (!(q.hausdorff <= max_hausdorff)) return fail;
  if (q.interior_valence.empty() && q.euler_in == 2) return fail << " (no interior nodes on a closed surface?)";
  return ::testing::AssertionSuccess() << "valence-3 share " << q.valence3_share;
}

// One remesh for the parameterised "ends valid" tests: a name for the test, the mesh, the
// panel count, the panel rounds (0: the default) and the bound on the Hausdorff distance.
struct ValidRemesh {
  std::string name;
  std::function<TriMesh()> mesh;
  int panels = 0;
  int panel_rounds = 0;
  double max_hausdorff = 0.08;
};

inline void PrintTo(const ValidRemesh& c, std::ostream* os) { *os << c.name; }
inline std::string valid_remesh_name(const ::testing::TestParamInfo<ValidRemesh>& info) { return info.param.name; }

// A Remesher of a shared mesh into `panels` at `seed`, otherwise the defaults, not yet run.
inline std::unique_ptr<Remesher> remesher(const std::string& file, int panels, std::uint64_t seed) {
  RemeshParams p;
  p.panels = panels;
  p.seed = seed;
  return std::make_unique<Remesher>(load_clean(file), p);
}

// The same, run to the end.
inline std::unique_ptr<Remesher> remeshed(const std::string& file, int panels, std::uint64_t seed) {
  auto r = remesher(file, panels, seed);
  r->run();
  return r;
}

// Remeshes c.mesh() with the default parameters but c's panel count and rounds.
inline ::testing::AssertionResult remeshes_valid(const ValidRemesh& c) {
  RemeshParams p;
  p.panels = c.panels;
  if (c.panel_rounds > 0) p.panel_rounds = c.panel_rounds;
  Remesher r(c.mesh(), p);
  r.run();
  return valid_panels(r, c.panels, c.max_hausdorff);
}

}  // namespace ff::test
