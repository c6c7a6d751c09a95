#pragma once
// CGAL's Variational Shape Approximation (Cohen-Steiner, Alliez, Desbrun 2004, as shipped in
// CGAL 5.x), driven the way bench_cluster and bench_remesh compare it with ours. Kept apart so that only
// cgal_vsa.cpp includes CGAL; this header is plain C++ and only declares what exists when
// the benchmark was built with -DFF_HAVE_CGAL.
#include <array>
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

// The whole VSA pipeline up to its output mesh, for bench_remesh: the same build, seeding and
// `iterations` x run(1) as run_cgal_vsa, then extract_mesh() and what it outputs.
struct CgalVsaMesh {
  double build_seconds = 0.0;    // TriMesh -> Surface_mesh, L21 metric
  double seed_seconds = 0.0;     // VSA object and initialize_seeds
  double iterate_seconds = 0.0;  // all run(1) calls
  double extract_seconds = 0.0;  // extract_mesh() and copying its output out
  int proxies = 0;
  double subdivision_ratio = 0.0;             // what extract_mesh was given
  bool manifold = false;                      // extract_mesh's answer: its triangle soup is a polygon mesh
  std::vector<Vec3> anchors;                  // anchor_points()
  std::vector<std::array<int, 3>> triangles;  // indexed_triangles(), into anchors
  // One anchor polygon per boundary cycle of a proxy region, in CGAL's cycle order; a
  // proxy with a hole (or a band around a tube) has several. Counter-clockwise seen from the
  // side the faces' normals point to, like the region it bounds.
  std::vector<std::vector<int>> polygons;
  std::vector<int> polygon_proxy;  // the proxy each polygon bounds
  std::vector<int> face_proxy;     // proxy per input face (TriMesh face order)
  // The polygons were rebuilt here (CGAL's own indexed_boundary_polygons does not say which
  // proxy a polygon bounds); true when they equal CGAL's, polygon for polygon.
  bool polygons_match_cgal = false;
};

// extract_mesh with subdivision_ratio(ratio) (CGAL's default 5: a chord between two anchors
// is split while the boundary strays farther than ratio x the mean edge length from it),
// and CGAL's defaults otherwise (absolute ratio, no dihedral weight, anchors moved onto the
// proxy planes, area-weighted proxy planes). Throws what CGAL throws.
CgalVsaMesh run_cgal_vsa_mesh(const ff::TriMesh& mesh, int panels, int iterations, unsigned seed,
                              double subdivision_ratio = 5.0);

// CGAL_VERSION_STR of the headers compiled in.
std::string cgal_version();

}  // namespace ff::bench
