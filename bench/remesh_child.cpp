#include "bench/remesh_child.h"

#include <sys/resource.h>

#include <exception>
#include <map>
#include <utility>

#include "bench/result_line.h"
#include "bench/stopwatch.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_mesh.h"
#include "core/quality/report.h"
#include "core/remesher.h"

#ifdef FF_HAVE_CGAL
#include "bench/cgal_panels.h"
#include "bench/cgal_vsa.h"
#endif

namespace ff::bench {

namespace {

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

int run_ours(const RemeshCase& c, const std::string& meshes, std::uint64_t seed, bool quality) {
  const Clock::time_point start = Clock::now();
  ff::TriMesh input = load_remesh_case(c, meshes);
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
int run_cgal(const RemeshCase& c, const std::string& meshes, std::uint64_t seed, bool quality, double ratio) {
  const Clock::time_point start = Clock::now();
  const ff::TriMesh input = load_remesh_case(c, meshes);
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
      // CGAL's polygons are not meant to be flat: judged by the paper's checks, as before
      // the quality report counted a bent panel invalid (their bend is the planarity column).
      ff::QualityOptions options;
      options.flat_panels = false;
      const ff::QualityReport q = ff::measure_quality(input, topology, polygon_panels(m, input.num_faces()), options);
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

}  // namespace

int run_remesh_only(const std::string& side, const RemeshCase& c, const std::string& meshes, std::uint64_t seed,
                    bool quality, double ratio) {
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

}  // namespace ff::bench
