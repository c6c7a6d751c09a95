#pragma once
// CGAL's Variational Shape Approximation (Cohen-Steiner, Alliez, Desbrun 2004, as shipped in
// CGAL 5.x), driven the way bench_cluster compares it with ours. Kept apart so that only
// cgal_vsa.cpp includes CGAL; this header is plain C++ and only declares what exists when
// the benchmark was built with -DFF_HAVE_CGAL.
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::bench {

struct CgalVsaRun {
  double build_seconds = 0.0;             // TriMesh -> CGAL::Surface_mesh, L21 metric (face normals, areas)
  double seed_seconds = 0.0;              // VSA object and initialize_seeds (random, no relaxation)
  std::vector<double> iteration_seconds;  // one entry per run(1)
  std::vector<int> labels;                // proxy index per face, in the TriMesh's face order
  int proxies = 0;                        // number of proxies after seeding
  double cgal_error = 0.0;                // CGAL's own total L2,1 error after the last iteration
};

// Random seeding of `panels` proxies (std::srand(seed) first: CGAL picks with std::rand),
// zero relaxations inside the seeding, then `iterations` calls of run(1) with the default
// L21 plane-proxy metric. Faces of the TriMesh become CGAL faces in the same order.
CgalVsaRun run_cgal_vsa(const ff::TriMesh& mesh, int panels, int iterations, unsigned seed);

// CGAL_VERSION_STR of the headers compiled in.
std::string cgal_version();

}  // namespace ff::bench
