#include "bench/cluster_child.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "bench/partition_energy.h"
#include "bench/stopwatch.h"
#include "core/cluster/clustering.h"
#include "core/remesher.h"

#ifdef FF_HAVE_CGAL
#include "bench/cgal_vsa.h"
#endif

namespace ff::bench {

namespace {

bool close_enough(double a, double b, double scale, double rel) {
  return std::abs(a - b) <= rel * std::max(scale, 1e-300);
}

struct Result {
  std::string method;
  int faces = 0;
  int panels = 0;
  int iterations = 0;
  double setup_a = 0.0;  // ours: topology + face data; CGAL: Surface_mesh + L21 metric data
  double setup_b = 0.0;  // seeding and the first partition (ours) / seeding (CGAL)
  std::vector<double> iteration_seconds;
  double energy = 0.0;      // l21_energy of the final partition
  double lib_energy = 0.0;  // the library's own report of the same (where it has one)
  std::string failure;      // empty when every check passed

  double setup() const { return setup_a + setup_b; }
  double iterations_total() const {
    double s = 0.0;
    for (double t : iteration_seconds) s += t;
    return s;
  }
};

Result run_ours(const std::string& method, ff::TriMesh mesh, int panels, int iterations, std::uint64_t seed) {
  Result r;
  r.method = method;
  r.faces = mesh.num_faces();
  r.panels = panels;
  ff::RemeshParams params;
  params.panels = panels;
  params.seed = seed;
  params.lloyd_iterations = iterations;
  // The clustering alone, like CGAL's run(): without this the Remesher goes on into the panel
  // phase, whose rounds would be timed as iterations and may change the cluster count.
  params.make_panels = false;
  if (method == "ours-l21") {
    // The same work as CGAL VSA's default: L2,1 only, random seeds, no teleports.
    params.weights.euclidean = 0.0;
    params.weights.l2 = 0.0;
    params.weights.l21 = 1.0;
    params.seeding = ff::SeedingMethod::Random;
    params.teleport_interval = 0;
  }  // ours-default: the product defaults (all weights 1, farthest-point seeds, teleports)
  Clock::time_point t = Clock::now();
  ff::Remesher remesher(std::move(mesh), params);
  r.setup_a = seconds_since(t);
  t = Clock::now();
  remesher.step();  // seeding + initial flood and fit
  r.setup_b = seconds_since(t);
  while (!remesher.done()) {
    t = Clock::now();
    remesher.step();
    r.iteration_seconds.push_back(seconds_since(t));
  }
  r.iterations = remesher.lloyd_iterations_done();

  const ff::Clustering& c = remesher.clustering();
  r.energy = l21_energy(remesher.mesh(), c.labels, c.num_clusters());
  r.lib_energy = remesher.energy().l21;
  if (c.num_clusters() != panels)
    r.failure = "expected " + std::to_string(panels) + " clusters, got " + std::to_string(c.num_clusters());
  else if (r.energy < 0.0)
    r.failure = "labels are not a partition into non-empty clusters";
  else if (!ff::clusters_are_contiguous(remesher.topology(), c.labels, c.num_clusters()))
    r.failure = "a cluster is not edge-connected";
  else if (!std::isfinite(r.energy))
    r.failure = "energy is not finite";
  else if (method == "ours-l21" && !close_enough(r.energy, r.lib_energy, remesher.metric().faces().total_area, 1e-9))
    r.failure = "our L2,1 energy disagrees with the library's";
  return r;
}

#ifdef FF_HAVE_CGAL
Result run_cgal(const ff::TriMesh& mesh, int panels, int iterations, unsigned seed) {
  Result r;
  r.method = "cgal";
  r.faces = mesh.num_faces();
  r.panels = panels;
  CgalVsaRun run = run_cgal_vsa(mesh, panels, iterations, seed);
  r.setup_a = run.build_seconds;
  r.setup_b = run.seed_seconds;
  r.iteration_seconds = run.iteration_seconds;
  r.iterations = static_cast<int>(run.iteration_seconds.size());
  r.energy = l21_energy(mesh, run.labels, run.proxies);
  r.lib_energy = run.cgal_error;
  const double area = ff::total_area(mesh);
  if (run.proxies != panels)
    r.failure = "CGAL made " + std::to_string(run.proxies) + " proxies, asked for " + std::to_string(panels);
  else if (r.energy < 0.0)
    r.failure = "CGAL labels are not a partition into non-empty clusters";
  else if (!std::isfinite(r.energy))
    r.failure = "energy is not finite";
  else if (iterations > 0 && !close_enough(r.energy, r.lib_energy, area, 1e-9))
    r.failure = "our L2,1 energy of CGAL's partition disagrees with CGAL's error";
  return r;
}
#endif

}  // namespace

int run_cluster_only(const std::string& method, const Case& c, const std::string& meshes, int iterations,
                     std::uint64_t seed) {
  ff::TriMesh mesh = make_input(c, meshes);
  Result r;
  if (method == "input") {
    r.method = method;
    r.faces = mesh.num_faces();
    r.panels = c.panels;
  } else if (method == "ours-l21" || method == "ours-default") {
    r = run_ours(method, std::move(mesh), c.panels, iterations, seed);
  } else if (method == "cgal") {
#ifdef FF_HAVE_CGAL
    r = run_cgal(mesh, c.panels, iterations, static_cast<unsigned>(seed));
#else
    std::fprintf(stderr, "bench_cluster: built without CGAL\n");
    return 2;
#endif
  } else {
    std::fprintf(stderr, "bench_cluster: unknown method '%s'\n", method.c_str());
    return 2;
  }
  std::printf(
      "result faces=%d panels=%d iterations=%d setup_a=%.9g setup_b=%.9g iter_total=%.9g energy=%.17g "
      "lib_energy=%.17g\n",
      r.faces, r.panels, r.iterations, r.setup_a, r.setup_b, r.iterations_total(), r.energy, r.lib_energy);
  std::fflush(stdout);
  if (!r.failure.empty()) {
    std::fprintf(stderr, "bench_cluster: %s on %s: %s\n", method.c_str(), c.name.c_str(), r.failure.c_str());
    return 3;
  }
  return 0;
}

}  // namespace ff::bench
