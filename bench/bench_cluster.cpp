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
// This file is the parent's side, the table; the child's is cluster_child.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bench/bench_case.h"
#include "bench/bench_options.h"
#include "bench/child_process.h"
#include "bench/cluster_child.h"
#include "bench/report_text.h"
#include "bench/result_line.h"

namespace {

using namespace ff::bench;

// What a child measured, and how it went.
struct Measured : ResultValues {
  bool ok = false;
  std::string error;
  double process_seconds = 0.0;  // wall clock from fork to exit
  double process_cpu = 0.0;      // the child's user + system CPU time
  double peak_rss_mib = 0.0;     // the child's ru_maxrss
};

Measured measure_once(const std::string& exe, const std::string& method, const Case& c, const std::string& meshes,
                      int iterations, std::uint64_t seed) {
  const ChildRun run = run_child({exe, "--only", method, "--case", c.name, "--meshes", meshes, "--iterations",
                                  std::to_string(iterations), "--seed", std::to_string(seed)});
  Measured m;
  m.process_seconds = run.wall_seconds;
  m.process_cpu = run.cpu_seconds;
  m.peak_rss_mib = run.peak_rss_mib;
  read_result(run.out, m);
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

std::string method_label(const std::string& method) {
  if (method == "ours-l21") return "ours: L2,1, random, no teleport";
  if (method == "ours-default") return "ours: default (all weights, farthest-point, teleport)";
  if (method == "cgal") return "CGAL VSA: L21, random";
  return method;
}

struct Options : BenchOptions {
  int iterations = -1;  // --iterations N
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
    if (mesh_file_missing(o.meshes, c.file, c.label, notes)) continue;
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
  return finish_report("bench_cluster", notes, failures);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  const auto own_flag = [&](const std::string& flag, const std::function<std::string()>& value) {
    if (flag != "--iterations") return Flag::Unknown;
    o.iterations = std::atoi(value().c_str());
    return Flag::Taken;
  };
  const auto run_only = [&] {
    Case c;
    if (!parse_case(o.case_name, c)) {
      std::fprintf(stderr,
                   "bench_cluster: --only needs --case (roof-10k, roof-100k, roof-1m, hyperboloid, roof:F:N)\n");
      return 2;
    }
    return run_cluster_only(o.only, c, o.meshes, o.iterations >= 0 ? o.iterations : 20, o.seed);
  };
  const auto table = [&](const char* argv0) { return run_table(o, argv0); };
  return bench_main(argc, argv, o, {"bench_cluster", usage, own_flag, run_only, table});
}
