// bench_remesh: the whole remeshing process, ours against CGAL's Variational Shape
// Approximation with its mesh extraction, at equal panel count (bench/README.md).
//
//   bench_remesh                  full run, Markdown tables on stdout
//   bench_remesh --smoke          a ~3k-triangle saddle into 40 panels, one run of each side;
//                                 exits non-zero when either side fails (scripts/test.sh)
//   bench_remesh --only ours|cgal --case CASE [--no-quality]
//                                 one run in this process, one "result ..." line; what the
//                                 parent runs in a child per measurement, and what to profile
//
// Ours: read + clean the mesh, ff::Remesher with the default RemeshParams but panels and seed,
// stepped to Done, then ff::measure_quality against the cleaned input. CGAL: the same read +
// clean, then Surface_mesh + L21 metric, random seeds, 20 x run(1), extract_mesh(); its
// anchor polygons become an ff::PanelMesh measured by the same measure_quality. Every run is
// a fresh child process (fork + exec of this binary): a CGAL crash is contained there and
// recorded as "failed", and each peak RSS is the child's own.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/child_process.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/polygon2d.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "core/shapes/hard_cases.h"

#ifdef FF_HAVE_CGAL
#include "bench/cgal_vsa.h"
#endif

#ifndef FF_DEFAULT_SHARED_MESHES
#define FF_DEFAULT_SHARED_MESHES "../shared/meshes"
#endif

namespace {

using namespace ff::bench;
using Clock = std::chrono::steady_clock;

constexpr int kCgalIterations = 20;  // as bench_cluster; ours runs its default k1 = 20 as well
// A child's exit code when the solve ran (its "result" line has the times) but measuring the
// result failed: measure_quality refused the panels (e.g. a non-finite vertex).
constexpr int kQualityFailed = 5;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// ---------------------------------------------------------------------------------------
// Cases

struct RemeshCase {
  std::string name;   // command-line id
  std::string label;  // table label
  std::string file;   // a file in the meshes folder, or
  std::string shape;  // "saddle" / "torus" (core/shapes/hard_cases.h) of about `triangles`
  int triangles = 0;
  int panels = 0;
};

const std::vector<std::string> kFullRun = {"hyperboloid", "inspired", "bunny", "fandisk", "face", "saddle", "torus"};
const char* const kSmokeCase = "saddle:3000:40";

// Named cases, or "saddle:TRIANGLES:PANELS", "torus:TRIANGLES:PANELS", "mesh:FILE:PANELS".
bool parse_case(const std::string& name, RemeshCase& c) {
  struct Named {
    const char *name, *file, *shape;
    int triangles, panels;
  };
  static const Named named[] = {
      {"hyperboloid", "hyperboloid_s4.off", "", 0, 500},
      {"inspired", "inspired_mesh.obj", "", 0, 100},
      {"bunny", "bunny.off", "", 0, 200},
      {"fandisk", "fandisk.off", "", 0, 300},
      {"face", "face.obj", "", 0, 500},
      {"saddle", "", "saddle", 20000, 200},
      {"torus", "", "torus", 20000, 200},
  };
  c = RemeshCase{};
  c.name = name;
  for (const Named& n : named) {
    if (name != n.name) continue;
    c.file = n.file;
    c.shape = n.shape;
    c.triangles = n.triangles;
    c.panels = n.panels;
  }
  if (c.file.empty() && c.shape.empty()) {
    const size_t a = name.find(':'), b = name.rfind(':');
    if (a == std::string::npos || a == b) return false;
    const std::string kind = name.substr(0, a), middle = name.substr(a + 1, b - a - 1);
    c.panels = std::atoi(name.c_str() + b + 1);
    if (kind == "mesh") {
      c.file = middle;
    } else if (kind == "saddle" || kind == "torus") {
      c.shape = kind;
      c.triangles = std::atoi(middle.c_str());
      if (c.triangles < 2) return false;
    } else {
      return false;
    }
    if (c.panels < 1 || middle.empty()) return false;
  }
  c.label = !c.file.empty() ? c.file : c.shape + " ~" + std::to_string(c.triangles / 1000) + "k";
  return true;
}

// Read (or make) and clean: the part of the whole process both sides share.
ff::TriMesh load(const RemeshCase& c, const std::string& meshes) {
  if (c.shape == "saddle") return ff::clean_mesh(ff::make_saddle(c.triangles)).mesh;
  if (c.shape == "torus") return ff::clean_mesh(ff::make_torus(c.triangles)).mesh;
  return ff::clean_mesh(ff::read_mesh_file(meshes + "/" + c.file).mesh).mesh;
}

// ---------------------------------------------------------------------------------------
// One run (in the child). Prints "result k=v ..." and, when something failed, "error ...".

struct Usage {
  double cpu_seconds = 0.0;  // user + system since exec
  double peak_rss_mib = 0.0;
};

Usage self_usage() {
  struct rusage u {};
  getrusage(RUSAGE_SELF, &u);
  Usage out;
  out.cpu_seconds = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                    1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  out.peak_rss_mib = static_cast<double>(u.ru_maxrss) / 1024.0;  // KiB on Linux
  return out;
}

class ResultLine {
 public:
  void add(const std::string& key, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    text_ += " " + key + "=" + buf;
  }
  void print() const {
    std::printf("result%s\n", text_.c_str());
    std::fflush(stdout);
  }

 private:
  std::string text_;
};

void add_quality(ResultLine& line, const std::string& prefix, const ff::QualityReport& q) {
  line.add(prefix + "panels", q.panels);
  line.add(prefix + "vertices", q.vertices);
  line.add(prefix + "invalid", q.invalid_panels);
  line.add(prefix + "planarity", q.max_planarity);
  line.add(prefix + "hausdorff", q.hausdorff);
  line.add(prefix + "hausdorff_in_out", q.hausdorff_input_to_panels);  // the two halves, for a look
  line.add(prefix + "hausdorff_out_in", q.hausdorff_panels_to_input);  // with --only

  line.add(prefix + "topology", q.topology_preserved ? 1 : 0);
  line.add(prefix + "manifold", q.oriented_manifold ? 1 : 0);
  line.add(prefix + "euler_in", q.euler_in);
  line.add(prefix + "euler_out", q.euler_out);
  line.add(prefix + "loops_in", q.boundary_loops_in);
  line.add(prefix + "loops_out", q.boundary_loops_out);
  line.add(prefix + "valence3", q.valence3_share);
  line.add(prefix + "misoriented", q.misoriented_panels);
  line.add(prefix + "flipped", q.flipped_edges);
  line.add(prefix + "non_star", q.non_star_panels);
  line.add(prefix + "non_simple", q.non_simple_panels);
  line.add(prefix + "spikes", q.spike_vertices);
}

void print_error(const std::string& what) {
  std::printf("error %s\n", what.c_str());
  std::fflush(stdout);
}

int run_ours(const RemeshCase& c, const std::string& meshes, std::uint64_t seed, bool quality) {
  const Clock::time_point start = Clock::now();
  ff::TriMesh input = load(c, meshes);
  const double input_s = seconds_since(start);
  const int faces = input.num_faces();

  ff::RemeshParams params;  // the defaults, but for the panel count and the seed
  params.panels = c.panels;
  params.seed = seed;
  Clock::time_point t = Clock::now();
  ff::Remesher remesher(std::move(input), params);
  const double prepare_s = seconds_since(t);
  // Stepping to Done is run(); stepping here only times the two phases apart.
  double lloyd_s = 0.0, panels_s = 0.0;
  while (!remesher.done()) {
    const ff::Stage stage = remesher.progress().stage;
    t = Clock::now();
    remesher.step();
    (stage == ff::Stage::Seeding || stage == ff::Stage::Lloyd ? lloyd_s : panels_s) += seconds_since(t);
  }
  const Usage usage = self_usage();  // before the quality report: the process as a user runs it

  ResultLine line;
  line.add("faces", faces);
  line.add("input_s", input_s);
  line.add("solve_s", prepare_s + lloyd_s + panels_s);
  line.add("prepare_s", prepare_s);
  line.add("lloyd_s", lloyd_s);
  line.add("panels_s", panels_s);
  line.add("lloyd_its", remesher.lloyd_iterations_done());
  line.add("panel_rounds", remesher.panel_rounds_done());
  line.add("cpu_s", usage.cpu_seconds);
  line.add("rss_mib", usage.peak_rss_mib);
  const ff::PanelMesh& panels = remesher.panels();
  line.add("unbuilt", static_cast<double>(panels.unbuilt_clusters.size()));
  line.add("own_panels", panels.num_panels());
  line.add("own_invalid", panels.num_invalid());
  if (quality) {
    try {
      t = Clock::now();
      const ff::QualityReport q = ff::measure_quality(remesher.mesh(), remesher.topology(), panels);
      line.add("quality_s", seconds_since(t));
      add_quality(line, "", q);
    } catch (const std::exception& e) {
      line.print();
      print_error(e.what());  // measure_quality's messages start with "quality:"
      return kQualityFailed;
    }
  }
  line.print();
  return 0;
}

#ifdef FF_HAVE_CGAL
// CGAL's anchor polygons as a PanelMesh: one panel per polygon, its plane through the
// polygon's vertex centroid with the Newell normal (CGAL's polygons are not planar, which
// is what max_planarity shows). No mesh corners (vertex_corner -1: no spike check), no
// issues of its own; face_panel maps a proxy's faces to its panel when it has exactly one.
ff::PanelMesh polygon_panels(const CgalVsaMesh& m, int faces) {
  ff::PanelMesh pm;
  pm.vertices = m.anchors;
  pm.panels = m.polygons;
  std::vector<int> proxy_panel(static_cast<size_t>(std::max(m.proxies, 0)), -1), cycles(proxy_panel.size(), 0);
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    std::vector<ff::Vec3> points;
    ff::Vec3 centroid = ff::Vec3::Zero();
    for (int v : pm.panels[p]) {
      points.push_back(pm.vertices[static_cast<size_t>(v)]);
      centroid += points.back();
    }
    if (!points.empty()) centroid /= static_cast<double>(points.size());
    ff::Vec3 n = ff::newell_normal(points);
    n = n.norm() > 0.0 ? ff::Vec3(n.normalized()) : ff::Vec3::UnitZ();
    pm.plane_normals.push_back(n);
    pm.plane_offsets.push_back(n.dot(centroid));
    const int proxy = m.polygon_proxy[p];
    pm.panel_cluster.push_back(proxy);
    if (proxy >= 0 && proxy < m.proxies) {
      proxy_panel[static_cast<size_t>(proxy)] = static_cast<int>(p);
      ++cycles[static_cast<size_t>(proxy)];
    }
  }
  pm.issues.resize(pm.panels.size());
  pm.vertex_corner.assign(pm.vertices.size(), -1);
  pm.face_panel.assign(static_cast<size_t>(faces), -1);
  for (int f = 0; f < faces; ++f) {
    const int proxy = m.face_proxy[static_cast<size_t>(f)];
    if (proxy >= 0 && proxy < m.proxies && cycles[static_cast<size_t>(proxy)] == 1)
      pm.face_panel[static_cast<size_t>(f)] = proxy_panel[static_cast<size_t>(proxy)];
  }
  return pm;
}

// CGAL's actual output, its indexed triangles over the anchors, as one panel per triangle:
// for its Hausdorff distance and topology next to the polygons'.
ff::PanelMesh triangle_panels(const CgalVsaMesh& m) {
  ff::PanelMesh pm;
  pm.vertices = m.anchors;
  for (const auto& t : m.triangles) {
    pm.panels.push_back({t[0], t[1], t[2]});
    const ff::Vec3 n = ff::newell_normal({m.anchors[static_cast<size_t>(t[0])], m.anchors[static_cast<size_t>(t[1])],
                                          m.anchors[static_cast<size_t>(t[2])]});
    pm.plane_normals.push_back(n.norm() > 0.0 ? ff::Vec3(n.normalized()) : ff::Vec3::UnitZ());
    pm.plane_offsets.push_back(pm.plane_normals.back().dot(m.anchors[static_cast<size_t>(t[0])]));
  }
  pm.issues.resize(pm.panels.size());
  pm.vertex_corner.assign(pm.vertices.size(), -1);
  return pm;
}

int run_cgal(const RemeshCase& c, const std::string& meshes, std::uint64_t seed, bool quality, double ratio) {
  const Clock::time_point start = Clock::now();
  const ff::TriMesh input = load(c, meshes);
  const double input_s = seconds_since(start);

  CgalVsaMesh m;
  try {
    m = run_cgal_vsa_mesh(input, c.panels, kCgalIterations, static_cast<unsigned>(seed), ratio);
  } catch (const std::exception& e) {
    print_error(std::string("CGAL: ") + e.what());
    return 4;
  } catch (...) {
    print_error("CGAL: unknown exception");
    return 4;
  }
  const Usage usage = self_usage();

  ResultLine line;
  line.add("faces", input.num_faces());
  line.add("input_s", input_s);
  line.add("solve_s", m.build_seconds + m.seed_seconds + m.iterate_seconds + m.extract_seconds);
  line.add("build_s", m.build_seconds);
  line.add("seed_s", m.seed_seconds);
  line.add("iterate_s", m.iterate_seconds);
  line.add("extract_s", m.extract_seconds);
  line.add("cpu_s", usage.cpu_seconds);
  line.add("rss_mib", usage.peak_rss_mib);
  line.add("proxies", m.proxies);
  line.add("anchors", static_cast<double>(m.anchors.size()));
  line.add("triangles", static_cast<double>(m.triangles.size()));
  line.add("cgal_manifold", m.manifold ? 1 : 0);
  line.add("polygons_match", m.polygons_match_cgal ? 1 : 0);
  std::map<int, int> cycles;
  for (int p : m.polygon_proxy) ++cycles[p];
  int multi = 0;
  for (const auto& [proxy, count] : cycles) multi += count > 1 ? 1 : 0;
  line.add("multi_cycle_proxies", multi);
  line.add("proxies_without_polygon", m.proxies - static_cast<int>(cycles.size()));
  if (quality) {
    try {
      const Clock::time_point t = Clock::now();
      const ff::MeshTopology topology = ff::build_topology(input);
      const ff::QualityReport q = ff::measure_quality(input, topology, polygon_panels(m, input.num_faces()));
      line.add("quality_s", seconds_since(t));
      add_quality(line, "", q);
      add_quality(line, "tri_", ff::measure_quality(input, topology, triangle_panels(m)));
    } catch (const std::exception& e) {
      line.print();
      print_error(std::string("measuring CGAL's output: ") + e.what());
      return kQualityFailed;
    }
  }
  line.print();
  if (!m.polygons_match_cgal) {
    // Our rebuilt polygons are what gets measured: if they are not CGAL's, the row is wrong.
    print_error("the rebuilt anchor polygons differ from CGAL's indexed_boundary_polygons");
    return 6;
  }
  return 0;
}
#endif

int run_only(const std::string& side, const RemeshCase& c, const std::string& meshes, std::uint64_t seed, bool quality,
             double ratio) {
  try {
    if (side == "ours") return run_ours(c, meshes, seed, quality);
    if (side == "cgal") {
#ifdef FF_HAVE_CGAL
      return run_cgal(c, meshes, seed, quality, ratio);
#else
      (void)ratio;
      print_error("built without CGAL");
      return 2;
#endif
    }
    print_error("unknown side '" + side + "'");
    return 2;
  } catch (const std::exception& e) {
    print_error(e.what());
    return 1;
  }
}

// ---------------------------------------------------------------------------------------
// The parent's side: a child per run.

struct Measured {
  bool ok = false;            // the solve ran and reported its times
  std::string error;          // why not
  std::string quality_error;  // the solve ran, but measuring its result failed
  std::map<std::string, double> values;
  double peak_rss_mib = 0.0;  // largest over the runs, before the quality report

  double num(const std::string& key) const {
    const auto it = values.find(key);
    return it == values.end() ? NAN : it->second;
  }
  bool has(const std::string& key) const { return values.count(key) != 0; }
  double total() const { return num("input_s") + num("solve_s"); }
};

Measured measure_once(const std::string& exe, const std::string& side, const RemeshCase& c, const std::string& meshes,
                      std::uint64_t seed, bool quality, double ratio) {
  char ratio_text[32];
  std::snprintf(ratio_text, sizeof ratio_text, "%.17g", ratio);
  std::vector<std::string> args = {exe, "--only", side, "--case", c.name, "--meshes", meshes};
  args.insert(args.end(), {"--seed", std::to_string(seed), "--subdivision-ratio", ratio_text});
  if (!quality) args.push_back("--no-quality");
  const ChildRun run = run_child(args);
  Measured m;
  std::istringstream lines(run.out);
  std::string line, error;
  while (std::getline(lines, line)) {
    if (line.rfind("error ", 0) == 0) error = line.substr(6);
    if (line.rfind("result ", 0) != 0) continue;
    std::istringstream fields(line.substr(7));
    std::string kv;
    while (fields >> kv) {
      const size_t eq = kv.find('=');
      if (eq != std::string::npos) m.values[kv.substr(0, eq)] = std::strtod(kv.c_str() + eq + 1, nullptr);
    }
  }
  m.peak_rss_mib = m.num("rss_mib");
  const bool quality_failed = !run.ok && run.error == "exit code " + std::to_string(kQualityFailed);
  m.ok = (run.ok || quality_failed) && !m.values.empty();
  if (m.ok && quality_failed) m.quality_error = error;
  if (!m.ok) m.error = !error.empty() ? error : (!run.ok ? run.error : "no result");
  if (!run.ok && !error.empty() && run.error.rfind("killed", 0) == 0) m.error += " (" + run.error + ")";
  return m;
}

// The quality numbers from the first run (they are deterministic); the time from the fastest
// of `repeat` runs, the later ones without the quality report; the largest peak RSS.
Measured measure(const std::string& exe, const std::string& side, const RemeshCase& c, const std::string& meshes,
                 std::uint64_t seed, int repeat, double ratio) {
  Measured first = measure_once(exe, side, c, meshes, seed, true, ratio);
  if (!first.ok) return first;
  Measured best = first;
  for (int r = 1; r < repeat; ++r) {
    const Measured m = measure_once(exe, side, c, meshes, seed, false, ratio);
    if (!m.ok) return m;
    first.peak_rss_mib = std::max(first.peak_rss_mib, m.peak_rss_mib);
    if (m.total() < best.total()) best = m;
  }
  for (const char* key : {"input_s", "solve_s", "prepare_s", "lloyd_s", "panels_s", "build_s", "seed_s", "iterate_s",
                          "extract_s", "cpu_s"}) {
    if (best.has(key)) first.values[key] = best.num(key);
  }
  return first;
}

std::string fmt(const char* format, double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string pair(const std::string& ours, const std::string& cgal) { return ours + " / " + cgal; }

std::string topology_cell(const Measured& m, const std::string& prefix = "") {
  if (!m.ok) return "-";
  if (m.num(prefix + "topology") == 1) return "yes";
  if (m.num(prefix + "manifold") != 1) return "no: non-manifold";
  return "no: χ " + fmt("%.0f", m.num(prefix + "euler_in")) + "→" + fmt("%.0f", m.num(prefix + "euler_out")) +
         ", loops " + fmt("%.0f", m.num(prefix + "loops_in")) + "→" + fmt("%.0f", m.num(prefix + "loops_out"));
}

std::string invalid_cell(const Measured& m) {
  if (!m.ok) return "-";
  // Clusters that never became a panel are invalid panels too (PanelMesh::num_invalid).
  const double unbuilt = m.has("unbuilt") ? m.num("unbuilt") : 0.0;
  std::string s = fmt("%.0f", m.num("invalid") + unbuilt);
  if (unbuilt > 0) s += " (" + fmt("%.0f", unbuilt) + " unbuilt)";
  // Ours: where the panel phase's own count (its PanelIssues) disagrees with the report's.
  if (m.has("own_invalid") && m.num("own_invalid") != m.num("invalid") + unbuilt)
    s += " (own " + fmt("%.0f", m.num("own_invalid")) + ")";
  return s;
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double a = NAN, b = NAN, c = NAN;
  in >> a >> b >> c;
  return fmt("%.2f", a) + " " + fmt("%.2f", b) + " " + fmt("%.2f", c);
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
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#else
  const std::string compiler = std::string("GCC ") + __VERSION__;
#endif
  std::string cgal = "without CGAL";
#ifdef FF_HAVE_CGAL
  cgal = "CGAL " + cgal_version();
#endif
  return cpu + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores; " + compiler + "; " + cgal;
}

struct Options {
  bool smoke = false;
  bool quality = true;
  std::string only;
  std::string case_name;
  std::vector<std::string> cases;
  std::string meshes;
  int repeat = 1;
  std::uint64_t seed = 1;
  double subdivision_ratio = 5.0;  // CGAL's default for extract_mesh
};

void usage() {
  std::fprintf(stderr,
               "usage: bench_remesh [--smoke] [--cases a,b,...] [--meshes DIR] [--seed S] [--repeat R]\n"
               "                    [--subdivision-ratio R]\n"
               "       bench_remesh --only ours|cgal --case CASE [--meshes DIR] [--seed S] [--no-quality]\n"
               "                    [--subdivision-ratio R]\n"
               "cases: hyperboloid inspired bunny fandisk face saddle torus, or saddle:TRIANGLES:PANELS,\n"
               "       torus:TRIANGLES:PANELS, mesh:FILE:PANELS\n");
}

double geometric_mean(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double s = 0.0;
  for (double x : v) s += std::log(x);
  return std::exp(s / static_cast<double>(v.size()));
}

int run_table(const Options& o, const char* argv0) {
  const std::string exe = self_path(argv0);
  std::vector<std::string> names = o.cases;
  if (names.empty()) names = o.smoke ? std::vector<std::string>{kSmokeCase} : kFullRun;
  std::vector<RemeshCase> cases(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    if (!parse_case(names[i], cases[i])) {
      std::fprintf(stderr, "bench_remesh: unknown case '%s'\n", names[i].c_str());
      usage();
      return 2;
    }
  }
  const int repeat = o.smoke ? 1 : std::max(1, o.repeat);
  bool with_cgal = false;
#ifdef FF_HAVE_CGAL
  with_cgal = true;
#endif

  std::printf("## Whole-process benchmark: ours vs CGAL VSA + extract_mesh, equal panel count\n\n");
  std::printf("Machine: %s.  \n", machine_line().c_str());
  std::printf("Load average (1, 5, 15 min) at the start: %s.  \n", load_average().c_str());
  std::printf(
      "Seed %llu; ours: default RemeshParams; CGAL: L21, random seeds, %d x run(1), extract_mesh(subdivision_ratio "
      "%g); every run in its own child process, time = best of %d, quality from the first run.\n\n",
      static_cast<unsigned long long>(o.seed), kCgalIterations, o.subdivision_ratio, repeat);
  std::printf(
      "| input | faces | n | panels ours / CGAL | invalid ours / CGAL | max planarity ours / CGAL | "
      "Hausdorff ours / CGAL | Hausdorff ratio | topology ours / CGAL | valence-3 ours / CGAL | "
      "time s ours / CGAL | time ratio | peak RSS MiB ours / CGAL |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|\n");
  std::fflush(stdout);

  struct Row {
    RemeshCase c;
    Measured ours, cgal;
  };
  std::vector<Row> rows;
  std::vector<std::string> notes;
  int failures = 0;
  std::vector<double> hausdorff_ratios, triangle_ratios, time_ratios;
  for (const RemeshCase& c : cases) {
    Row row;
    row.c = c;
    if (!c.file.empty() && access((o.meshes + "/" + c.file).c_str(), R_OK) != 0) {
      notes.push_back(c.label + " skipped: " + o.meshes + "/" + c.file + " not found (pass --meshes DIR)");
      continue;
    }
    row.ours = measure(exe, "ours", c, o.meshes, o.seed, repeat, o.subdivision_ratio);
    if (!row.ours.ok || !row.ours.quality_error.empty()) {
      ++failures;
      const std::string why = row.ours.ok ? row.ours.quality_error : row.ours.error;
      std::fprintf(stderr, "bench_remesh: %s / ours failed: %s\n", c.label.c_str(), why.c_str());
      std::string own;
      if (row.ours.ok)
        own = " (its PanelMesh: " + fmt("%.0f", row.ours.num("own_panels")) + " panels, " +
              fmt("%.0f", row.ours.num("own_invalid")) + " invalid by its own PanelIssues)";
      notes.push_back(c.label + ": ours failed: " + why + own);
    }
    if (with_cgal) {
      row.cgal = measure(exe, "cgal", c, o.meshes, o.seed, repeat, o.subdivision_ratio);
      if (!row.cgal.ok || !row.cgal.quality_error.empty()) {
        // A CGAL failure on a real input is a finding; in the smoke run, or when the polygons we
        // rebuilt are not CGAL's, it means our driver broke.
        const std::string why = row.cgal.ok ? row.cgal.quality_error : row.cgal.error;
        if (o.smoke || why.find("rebuilt") != std::string::npos) ++failures;
        std::fprintf(stderr, "bench_remesh: %s / CGAL failed: %s\n", c.label.c_str(), why.c_str());
        notes.push_back(c.label + ": CGAL failed: " + why);
      }
    } else {
      row.cgal.error = "built without CGAL";
    }
    const Measured& a = row.ours;
    const Measured& b = row.cgal;
    const double faces = a.ok ? a.num("faces") : b.num("faces");
    const bool both = a.ok && b.ok;
    // NaN (not counted) where a side failed or has no quality numbers.
    const double h_ratio = both ? a.num("hausdorff") / b.num("hausdorff") : NAN;
    const double tri_ratio = both ? a.num("hausdorff") / b.num("tri_hausdorff") : NAN;
    const double t_ratio = both ? a.total() / b.total() : NAN;
    if (std::isfinite(h_ratio) && h_ratio > 0.0) hausdorff_ratios.push_back(h_ratio);
    if (std::isfinite(tri_ratio) && tri_ratio > 0.0) triangle_ratios.push_back(tri_ratio);
    if (std::isfinite(t_ratio) && t_ratio > 0.0) time_ratios.push_back(t_ratio);
    const std::string cgal_failed = with_cgal ? "failed" : "-";
    // Cells of the solve (time, RSS), and cells of the quality report.
    const auto side = [&](const Measured& m, const std::string& text) {
      return m.ok ? text : (&m == &b ? cgal_failed : std::string("FAILED"));
    };
    const auto measured = [&](const Measured& m, const std::string& text) {
      return m.ok && !m.quality_error.empty() ? (&m == &b ? cgal_failed : std::string("FAILED")) : side(m, text);
    };
    const auto panels = [&](const Measured& m) {
      return side(m, fmt("%.0f", m.has("panels") ? m.num("panels") : m.num("own_panels")));
    };
    std::printf(
        "| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.label.c_str(),
        fmt("%.0f", faces).c_str(), c.panels, pair(panels(a), panels(b)).c_str(),
        pair(measured(a, invalid_cell(a)), measured(b, invalid_cell(b))).c_str(),
        pair(measured(a, fmt("%.1e", a.num("planarity"))), measured(b, fmt("%.1e", b.num("planarity")))).c_str(),
        pair(measured(a, fmt("%.5f", a.num("hausdorff"))), measured(b, fmt("%.5f", b.num("hausdorff")))).c_str(),
        fmt("%.2f", h_ratio).c_str(), pair(measured(a, topology_cell(a)), measured(b, topology_cell(b))).c_str(),
        pair(measured(a, fmt("%.0f%%", 100.0 * a.num("valence3"))),
             measured(b, fmt("%.0f%%", 100.0 * b.num("valence3"))))
            .c_str(),
        pair(side(a, fmt("%.3f", a.total())), side(b, fmt("%.3f", b.total()))).c_str(), fmt("%.2f", t_ratio).c_str(),
        pair(side(a, fmt("%.0f", a.peak_rss_mib)), side(b, fmt("%.0f", b.peak_rss_mib))).c_str());
    std::fflush(stdout);
    rows.push_back(row);
  }
  if (!hausdorff_ratios.empty() || !time_ratios.empty()) {
    std::printf("| geometric mean (Hausdorff: %zu inputs, time: %zu) | | | | | | | %s | | | | %s | |\n",
                hausdorff_ratios.size(), time_ratios.size(), fmt("%.2f", geometric_mean(hausdorff_ratios)).c_str(),
                fmt("%.2f", geometric_mean(time_ratios)).c_str());
  }
  std::printf(
      "\nPanels: ours = panels of the final PanelMesh; CGAL = anchor polygons (one per boundary cycle of a proxy "
      "region). Invalid: measure_quality's invalid panels (plus, for ours, clusters left unbuilt; (own K): the panel "
      "phase's own count K where it differs). Max planarity: max "
      "over panels of the largest vertex distance to the panel's least-squares plane / its diameter. Hausdorff: "
      "two-sided, sampled, / input bbox diagonal, against the cleaned input; ratio = ours / CGAL. Time: read + clean "
      "+ solve, wall clock inside the child (ours: Remesher to Done; CGAL: Surface_mesh + metric, seeding, %d "
      "iterations, extract_mesh), quality report excluded; ratio = ours / CGAL. Peak RSS: the child's, before the "
      "quality report.\n\n",
      kCgalIterations);
  if (!triangle_ratios.empty()) {
    // CGAL's own output is the triangle mesh over the anchors; the polygons above are what a
    // panel would be. Both Hausdorff distances are given so neither reading hides the other.
    std::printf(
        "Hausdorff of ours / CGAL's indexed triangles (its actual output mesh, not panels), geometric mean over %zu "
        "inputs: %s.\n\n",
        triangle_ratios.size(), fmt("%.2f", geometric_mean(triangle_ratios)).c_str());
  }

  // Where the time goes, and what CGAL's own output looks like.
  std::printf(
      "| input | ours: vertices (spikes) | read+clean s | prepare s | Lloyd s (iterations) | panels s (rounds) | "
      "quality s | "
      "CPU s | "
      "CGAL: read+clean s | build s | seeding s | %d iterations s | extract s | quality s | CPU s | "
      "CGAL: proxies / polygons / vertices / triangles | CGAL says manifold | CGAL triangles: Hausdorff, topology |\n",
      kCgalIterations);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  for (const Row& row : rows) {
    const Measured& a = row.ours;
    const Measured& b = row.cgal;
    std::string ours_cells = "| FAILED: " + a.error + " | | | | | | ";
    if (a.ok) {
      ours_cells = "| " + fmt("%.0f", a.num("vertices")) + " (" + fmt("%.0f", a.num("spikes")) + ") | " +
                   fmt("%.3f", a.num("input_s")) + " | " + fmt("%.3f", a.num("prepare_s")) + " | " +
                   fmt("%.3f", a.num("lloyd_s")) + " (" + fmt("%.0f", a.num("lloyd_its")) + ") | " +
                   fmt("%.3f", a.num("panels_s")) + " (" + fmt("%.0f", a.num("panel_rounds")) + ") | " +
                   fmt("%.2f", a.num("quality_s")) + " | " + fmt("%.2f", a.num("cpu_s")) + " ";
    }
    std::string cgal_cells = "| " + (with_cgal ? "failed: " + b.error : std::string("-")) + " | | | | | | | | | ";
    if (b.ok) {
      cgal_cells = "| " + fmt("%.3f", b.num("input_s")) + " | " + fmt("%.3f", b.num("build_s")) + " | " +
                   fmt("%.3f", b.num("seed_s")) + " | " + fmt("%.3f", b.num("iterate_s")) + " | " +
                   fmt("%.3f", b.num("extract_s")) + " | " + fmt("%.2f", b.num("quality_s")) + " | " +
                   fmt("%.2f", b.num("cpu_s")) + " | " + fmt("%.0f", b.num("proxies")) + " / " +
                   fmt("%.0f", b.num("panels")) + " / " + fmt("%.0f", b.num("vertices")) + " / " +
                   fmt("%.0f", b.num("triangles")) + " | " + (b.num("cgal_manifold") == 1 ? "yes" : "no") + " | " +
                   fmt("%.5f", b.num("tri_hausdorff")) + ", " + topology_cell(b, "tri_") + " ";
    }
    std::printf("| %s %s%s|\n", row.c.label.c_str(), ours_cells.c_str(), cgal_cells.c_str());
  }
  std::printf(
      "\nCPU s: user + system time of the whole child up to the end of the solve (read, clean, solve, and the "
      "process start). CGAL says manifold: extract_mesh()'s return value (its triangle soup is an oriented "
      "polygon mesh).\n\n");

  for (const Row& row : rows) {
    const Measured& b = row.cgal;
    if (b.ok && b.num("multi_cycle_proxies") > 0)
      notes.push_back(row.c.label + ": " + fmt("%.0f", b.num("multi_cycle_proxies")) +
                      " CGAL proxy region(s) have more than one boundary cycle: each cycle is its own polygon");
    if (b.ok && b.num("proxies_without_polygon") > 0)
      notes.push_back(row.c.label + ": " + fmt("%.0f", b.num("proxies_without_polygon")) +
                      " CGAL proxy region(s) have no boundary (a closed part): no polygon");
  }
  if (!o.smoke) {
    for (const Row& row : rows) {
      if (row.c.name != "hyperboloid" || !row.ours.ok) continue;
      std::printf(
          "Target hyperboloid_s4.off into %d panels under 1 s native (ours, read + clean + remesh): %.3f s: %s."
          "  \n",
          row.c.panels, row.ours.total(), row.ours.total() < 1.0 ? "met" : "MISSED");
    }
    int compared = 0, compared_quality = 0, lower = 0, faster = 0;
    for (const Row& row : rows) {
      if (!row.ours.ok || !row.cgal.ok) continue;
      ++compared;
      faster += row.ours.total() <= row.cgal.total() ? 1 : 0;
      if (!row.ours.has("hausdorff") || !row.cgal.has("hausdorff")) continue;
      ++compared_quality;
      lower += row.ours.num("hausdorff") < row.cgal.num("hausdorff") ? 1 : 0;
    }
    if (compared > 0) {
      std::printf("Target Hausdorff lower than CGAL VSA at equal panel count (DESIGN.md 5): %d of %d inputs.  \n",
                  lower, compared_quality);
      std::printf(
          "Target whole process no slower than CGAL VSA clustering + extraction (DESIGN.md 7): %d of %d inputs.\n",
          faster, compared);
    }
  }
  std::printf("\nLoad average (1, 5, 15 min) at the end: %s.\n", load_average().c_str());
  for (const std::string& n : notes) std::printf("\nNote: %s\n", n.c_str());
  std::fflush(stdout);
  if (failures > 0) {
    std::fprintf(stderr, "bench_remesh: %d measurement(s) failed\n", failures);
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
        std::fprintf(stderr, "bench_remesh: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--smoke") {
      o.smoke = true;
    } else if (a == "--no-quality") {
      o.quality = false;
    } else if (a == "--only") {
      o.only = value();
    } else if (a == "--case") {
      o.case_name = value();
    } else if (a == "--cases") {
      std::istringstream list(value());
      std::string item;
      while (std::getline(list, item, ',')) {
        if (!item.empty()) o.cases.push_back(item);
      }
    } else if (a == "--meshes") {
      o.meshes = value();
    } else if (a == "--repeat") {
      o.repeat = std::atoi(value().c_str());
    } else if (a == "--subdivision-ratio") {
      o.subdivision_ratio = std::strtod(value().c_str(), nullptr);
      if (!(o.subdivision_ratio > 0.0)) {
        std::fprintf(stderr, "bench_remesh: --subdivision-ratio must be positive\n");
        return 2;
      }
    } else if (a == "--seed") {
      o.seed = std::strtoull(value().c_str(), nullptr, 10);
    } else if (a == "--help" || a == "-h") {
      usage();
      return 0;
    } else {
      std::fprintf(stderr, "bench_remesh: unknown argument '%s'\n", a.c_str());
      usage();
      return 2;
    }
  }
  try {
    if (!o.only.empty()) {
      RemeshCase c;
      if (!parse_case(o.case_name, c)) {
        std::fprintf(stderr, "bench_remesh: --only needs --case (see --help)\n");
        return 2;
      }
      return run_only(o.only, c, o.meshes, o.seed, o.quality, o.subdivision_ratio);
    }
    return run_table(o, argv[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_remesh: %s\n", e.what());
    return 1;
  }
}
