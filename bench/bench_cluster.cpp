// bench_cluster: our Lloyd clustering against CGAL's Variational Shape Approximation.
//
//   bench_cluster                 full run, Markdown table on stdout (see bench/README.md)
//   bench_cluster --smoke         ~5k-triangle roof, n = 50, 3 iterations, every method;
//                                 exits non-zero when anything fails (scripts/test.sh)
//   bench_cluster --only METHOD --case CASE
//                                 one measurement in this process, one "result ..." line;
//                                 what the parent runs in a child per table cell, and what
//                                 to run under a profiler
//
// Every (case, method) runs in a fresh child process (fork + exec of this binary) so the
// peak resident set of each is its own: wait4() returns the child's rusage, ru_maxrss.
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_case.h"
#include "bench/child_process.h"
#include "bench/partition_energy.h"
#include "core/cluster/clustering.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"

#ifdef FF_HAVE_CGAL
#include "bench/cgal_vsa.h"
#endif

#ifndef FF_DEFAULT_SHARED_MESHES
#define FF_DEFAULT_SHARED_MESHES "../shared/meshes"
#endif

namespace {

using namespace ff::bench;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool close_enough(double a, double b, double scale, double rel) {
  return std::abs(a - b) <= rel * std::max(scale, 1e-300);
}

// ---------------------------------------------------------------------------------------
// One measurement (in the child)

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
  ff::bench::CgalVsaRun run = ff::bench::run_cgal_vsa(mesh, panels, iterations, seed);
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

// The child's side: one method on one case, one line on stdout.
int run_only(const std::string& method, const Case& c, const std::string& meshes, int iterations, std::uint64_t seed) {
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

// ---------------------------------------------------------------------------------------
// The parent's side: a child per measurement.

struct Measured {
  bool ok = false;
  std::string error;
  std::map<std::string, std::string> values;
  double process_seconds = 0.0;  // wall clock from fork to exit
  double process_cpu = 0.0;      // the child's user + system CPU time
  double peak_rss_mib = 0.0;     // the child's ru_maxrss

  double num(const std::string& key) const {
    const auto it = values.find(key);
    return it == values.end() ? std::nan("") : std::strtod(it->second.c_str(), nullptr);
  }
};

Measured measure_once(const std::string& exe, const std::string& method, const Case& c, const std::string& meshes,
                      int iterations, std::uint64_t seed) {
  const ChildRun run = run_child({exe, "--only", method, "--case", c.name, "--meshes", meshes, "--iterations",
                                  std::to_string(iterations), "--seed", std::to_string(seed)});
  Measured m;
  m.process_seconds = run.wall_seconds;
  m.process_cpu = run.cpu_seconds;
  m.peak_rss_mib = run.peak_rss_mib;
  std::istringstream lines(run.out);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("result ", 0) != 0) continue;
    std::istringstream fields(line.substr(7));
    std::string kv;
    while (fields >> kv) {
      const size_t eq = kv.find('=');
      if (eq != std::string::npos) m.values[kv.substr(0, eq)] = kv.substr(eq + 1);
    }
  }
  m.ok = run.ok && !m.values.empty();
  m.error = !run.ok ? run.error : (m.values.empty() ? "no result" : "");
  return m;
}

// Best of `repeat` runs (least setup + iterations time; the input row: least wall time), so a
// busy machine disturbs the table less. Peak RSS is the largest seen over the runs.
Measured measure(const std::string& exe, const std::string& method, const Case& c, const std::string& meshes,
                 int iterations, std::uint64_t seed, int repeat) {
  Measured best;
  double best_time = INFINITY, rss = 0.0;
  for (int r = 0; r < std::max(1, repeat); ++r) {
    Measured m = measure_once(exe, method, c, meshes, iterations, seed);
    if (!m.ok) return m;
    rss = std::max(rss, m.peak_rss_mib);
    const double t = method == "input" ? m.process_seconds : m.num("setup_a") + m.num("setup_b") + m.num("iter_total");
    if (t < best_time) {
      best_time = t;
      best = m;
    }
  }
  best.peak_rss_mib = rss;
  return best;
}

std::string fmt(const char* format, double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string method_label(const std::string& method) {
  if (method == "ours-l21") return "ours: L2,1, random, no teleport";
  if (method == "ours-default") return "ours: default (all weights, farthest-point, teleport)";
  if (method == "cgal") return "CGAL VSA: L21, random";
  return method;
}

std::string machine_line() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  std::string line;
  while (std::getline(info, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) cpu = line.substr(colon + 2);
      break;
    }
  }
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("GCC ") + __VERSION__;
#else
  const std::string compiler = "unknown compiler";
#endif
  std::string cgal = "without CGAL";
#ifdef FF_HAVE_CGAL
  cgal = "CGAL " + ff::bench::cgal_version();
#endif
  return cpu + ", " + std::to_string(cores) + " cores; " + compiler + "; " + cgal;
}

struct Options {
  bool smoke = false;
  std::string only;
  std::string case_name;
  std::vector<std::string> cases;
  std::string meshes;
  int iterations = -1;
  int repeat = 1;
  std::uint64_t seed = 1;
};

void usage() {
  std::fprintf(
      stderr,
      "usage: bench_cluster [--smoke] [--cases a,b,...] [--meshes DIR] [--iterations N] [--seed S] [--repeat R]\n"
      "       bench_cluster --only input|ours-l21|ours-default|cgal --case CASE [--meshes DIR]\n"
      "                     [--iterations N] [--seed S]\n"
      "cases: roof-10k roof-100k roof-1m hyperboloid, or roof:FACES:PANELS\n");
}

int run_table(const Options& o, const char* argv0) {
  const std::string exe = self_path(argv0);
  const int iterations = o.iterations >= 0 ? o.iterations : (o.smoke ? 3 : 20);
  std::vector<std::string> names = o.cases;
  if (names.empty()) {
    names = o.smoke ? std::vector<std::string>{"roof:5000:50"}
                    : std::vector<std::string>{"roof-10k", "roof-100k", "roof-1m", "hyperboloid"};
  }
  std::vector<std::string> methods = {"ours-l21", "ours-default"};
#ifdef FF_HAVE_CGAL
  methods.push_back("cgal");
#endif

  int failures = 0;
  std::vector<std::string> notes;
  std::printf("## Clustering benchmark: ours vs CGAL Variational Shape Approximation\n\n");
  std::printf("Machine: %s.  \n", machine_line().c_str());
  std::printf("%d Lloyd iterations; seed %llu; every cell measured in its own child process, best of %d run(s).\n\n",
              iterations, static_cast<unsigned long long>(o.seed), std::max(1, o.repeat));
  std::printf(
      "| input | faces | n | method | iterations | setup s (a + b) | per iteration ms | iterations s | total s | "
      "process s (CPU s) | peak RSS MiB | L2,1 energy |\n");
  std::printf("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::fflush(stdout);

  struct Pair {
    std::string label;
    double ours_total = NAN, cgal_total = NAN, ours_process = NAN, cgal_process = NAN, ours_cpu = NAN, cgal_cpu = NAN,
           ours_energy = NAN, cgal_energy = NAN;
    int faces = 0, panels = 0;
  };
  std::vector<Pair> pairs;

  for (const std::string& name : names) {
    Case c;
    if (!parse_case(name, c)) {
      std::fprintf(stderr, "bench_cluster: unknown case '%s'\n", name.c_str());
      usage();
      return 2;
    }
    if (!c.file.empty() && access((o.meshes + "/" + c.file).c_str(), R_OK) != 0) {
      notes.push_back(c.label + " skipped: " + o.meshes + "/" + c.file + " not found (pass --meshes DIR)");
      continue;
    }
    const Measured base = measure(exe, "input", c, o.meshes, iterations, o.seed, o.repeat);
    if (!base.ok) {
      std::fprintf(stderr, "bench_cluster: %s: making the input failed (%s)\n", c.label.c_str(), base.error.c_str());
      ++failures;
      continue;
    }
    const int faces = static_cast<int>(base.num("faces"));
    std::printf("| %s | %d | %d | input only (make/read the mesh) | | | | | | %s (%s) | %s | |\n", c.label.c_str(),
                faces, c.panels, fmt("%.2f", base.process_seconds).c_str(), fmt("%.2f", base.process_cpu).c_str(),
                fmt("%.0f", base.peak_rss_mib).c_str());
    Pair pair;
    pair.label = c.label;
    pair.faces = faces;
    pair.panels = c.panels;
    for (const std::string& method : methods) {
      const Measured m = measure(exe, method, c, o.meshes, iterations, o.seed, o.repeat);
      if (!m.ok) {
        ++failures;
        std::fprintf(stderr, "bench_cluster: %s / %s failed: %s\n", c.label.c_str(), method.c_str(), m.error.c_str());
        std::printf("| %s | %d | %d | %s | FAILED: %s | | | | | | | |\n", c.label.c_str(), faces, c.panels,
                    method_label(method).c_str(), m.error.c_str());
        std::fflush(stdout);
        continue;
      }
      const int its = static_cast<int>(m.num("iterations"));
      const double sa = m.num("setup_a"), sb = m.num("setup_b"), it_total = m.num("iter_total");
      const double total = sa + sb + it_total;
      const std::string setup = fmt("%.3f", sa + sb) + " (" + fmt("%.3f", sa) + " + " + fmt("%.3f", sb) + ")";
      std::printf("| %s | %d | %d | %s | %d%s | %s | %s | %s | %s | %s (%s) | %s | %s |\n", c.label.c_str(), faces,
                  c.panels, method_label(method).c_str(), its, its < iterations ? " (converged)" : "", setup.c_str(),
                  fmt("%.1f", its > 0 ? 1000.0 * it_total / its : NAN).c_str(), fmt("%.3f", it_total).c_str(),
                  fmt("%.3f", total).c_str(), fmt("%.2f", m.process_seconds).c_str(),
                  fmt("%.2f", m.process_cpu).c_str(), fmt("%.0f", m.peak_rss_mib).c_str(),
                  fmt("%.6g", m.num("energy")).c_str());
      std::fflush(stdout);
      if (method == "ours-l21") {
        pair.ours_total = total;
        pair.ours_process = m.process_seconds;
        pair.ours_cpu = m.process_cpu;
        pair.ours_energy = m.num("energy");
      } else if (method == "cgal") {
        pair.cgal_total = total;
        pair.cgal_process = m.process_seconds;
        pair.cgal_cpu = m.process_cpu;
        pair.cgal_energy = m.num("energy");
      }
    }
    pairs.push_back(pair);
  }

  std::printf(
      "\nSetup: (a) ours = topology + face data, CGAL = Surface_mesh + L21 face normals/areas; "
      "(b) ours = seeding + first flood and fit, CGAL = seeding (VSA object, random seeds, no relaxation). "
      "Iterations: ours = choose seeds + flood + refit; CGAL = run(1) = partition + refit (+ its seed choice). "
      "Process = wall clock of the whole child, including making or reading the input. "
      "L2,1 energy = sum of area |n_f - N_i|^2 with N_i the area-weighted mean normal of the cluster, "
      "computed by the benchmark itself for every partition.\n\n");
  bool any_pair = false;
  for (const Pair& p : pairs) {
    if (std::isnan(p.cgal_total) || std::isnan(p.ours_total)) continue;
    if (!any_pair) {
      std::printf(
          "| input | ours L2,1 / CGAL: total time | process time | process CPU time | L2,1 energy |\n"
          "|---|---:|---:|---:|---:|\n");
      any_pair = true;
    }
    std::printf("| %s | %s | %s | %s | %s |\n", p.label.c_str(), fmt("%.2f", p.ours_total / p.cgal_total).c_str(),
                fmt("%.2f", p.ours_process / p.cgal_process).c_str(), fmt("%.2f", p.ours_cpu / p.cgal_cpu).c_str(),
                fmt("%.3f", p.ours_energy / p.cgal_energy).c_str());
  }
  if (any_pair) std::printf("\n");
  if (!o.smoke) {
    for (const Pair& p : pairs) {
      if (p.label != "roof ~1M" || std::isnan(p.ours_total)) continue;
      std::printf(
          "Target 1M triangles x %d clusters x %d iterations under 5 s (ours, L2,1): total %.2f s, "
          "process %.2f s: %s.  \n",
          p.panels, iterations, p.ours_total, p.ours_process, p.ours_total < 5.0 ? "met" : "MISSED");
    }
    bool slower = false, compared = false;
    for (const Pair& p : pairs) {
      if (std::isnan(p.cgal_process) || std::isnan(p.ours_process)) continue;
      compared = true;
      if (p.ours_process > p.cgal_process) slower = true;
    }
    if (compared)
      std::printf("Target whole-process time no slower than CGAL (ours L2,1 vs CGAL, every input): %s.\n",
                  slower ? "MISSED" : "met");
  }
  for (const std::string& n : notes) std::printf("\nNote: %s\n", n.c_str());
  std::fflush(stdout);
  if (failures > 0) {
    std::fprintf(stderr, "bench_cluster: %d measurement(s) failed\n", failures);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const char* env = std::getenv("FF_SHARED_MESHES"); env && *env)
    o.meshes = env;
  else
    o.meshes = FF_DEFAULT_SHARED_MESHES;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bench_cluster: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--smoke")
      o.smoke = true;
    else if (a == "--only")
      o.only = value();
    else if (a == "--case")
      o.case_name = value();
    else if (a == "--cases") {
      std::istringstream list(value());
      std::string item;
      while (std::getline(list, item, ',')) {
        if (!item.empty()) o.cases.push_back(item);
      }
    } else if (a == "--meshes")
      o.meshes = value();
    else if (a == "--iterations")
      o.iterations = std::atoi(value().c_str());
    else if (a == "--repeat")
      o.repeat = std::atoi(value().c_str());
    else if (a == "--seed")
      o.seed = std::strtoull(value().c_str(), nullptr, 10);
    else if (a == "--help" || a == "-h") {
      usage();
      return 0;
    } else {
      std::fprintf(stderr, "bench_cluster: unknown argument '%s'\n", a.c_str());
      usage();
      return 2;
    }
  }
  try {
    if (!o.only.empty()) {
      Case c;
      if (!parse_case(o.case_name, c)) {
        std::fprintf(stderr,
                     "bench_cluster: --only needs --case (roof-10k, roof-100k, roof-1m, hyperboloid, roof:F:N)\n");
        return 2;
      }
      return run_only(o.only, c, o.meshes, o.iterations >= 0 ? o.iterations : 20, o.seed);
    }
    return run_table(o, argv[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_cluster: %s\n", e.what());
    return 1;
  }
}
