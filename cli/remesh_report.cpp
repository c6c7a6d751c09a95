#include "cli/remesh_report.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "cli/commands.h"
#include "cli/json_writer.h"

namespace ff::cli {

namespace {

void write_quality(JsonWriter& j, const QualityReport& q) {
  j.value("max_planarity", q.max_planarity);
  // DESIGN.md 4: `hausdorff` is the two-sided distance (/ bbox diagonal); both halves follow.
  j.value("hausdorff", q.hausdorff);
  j.value("hausdorff_input_to_panels", q.hausdorff_input_to_panels);
  j.value("hausdorff_panels_to_input", q.hausdorff_panels_to_input);
  j.begin_array("hausdorff_worst_point");
  for (int k = 0; k < 3; ++k) j.value(nullptr, q.hausdorff_worst_point[k]);
  j.end_array();
  j.value("topology_preserved", q.topology_preserved);
  j.value("euler_in", q.euler_in).value("euler_out", q.euler_out);
  j.value("boundary_loops_in", q.boundary_loops_in).value("boundary_loops_out", q.boundary_loops_out);
  j.value("oriented_manifold", q.oriented_manifold);
  j.value("flipped_edges", q.flipped_edges);
  j.value("misoriented_panels", q.misoriented_panels);
  j.value("non_star_panels", q.non_star_panels);
  j.value("non_simple_panels", q.non_simple_panels);
  j.value("spike_vertices", q.spike_vertices);
  j.value("invalid_panels", q.invalid_panels);
  // JSON object keys are strings: {"3": 120, "4": 2}, in increasing valence (std::map order).
  j.begin_object("interior_valence");
  for (const auto& [valence, count] : q.interior_valence) j.value(std::to_string(valence).c_str(), count);
  j.end_object();
  j.value("valence3_share", q.valence3_share);
  j.value("min_corner_angle_deg", q.min_corner_angle_deg);
}

// Per invalid panel: where it came from and what is wrong, so nothing is hidden (DESIGN.md 3).
// The panels the quality measurement found invalid (which include those the panel phase
// flagged itself), plus any flagged one it missed, in increasing order.
void write_invalid(JsonWriter& j, const PanelMesh& pm, const QualityReport& q) {
  std::set<int> ids(q.invalid_panel_ids.begin(), q.invalid_panel_ids.end());
  for (size_t i = 0; i < pm.issues.size(); ++i)
    if (!pm.issues[i].valid()) ids.insert(static_cast<int>(i));
  j.begin_array("invalid");
  for (const int id : ids) {
    const size_t i = static_cast<size_t>(id);
    j.begin_object();
    j.value("panel", id);
    j.value("cluster", i < pm.panel_cluster.size() ? pm.panel_cluster[i] : -1);
    std::vector<std::string> problems;
    if (i < pm.issues.size()) problems = panel_problems(pm.issues[i]);
    // Valid by its own flags but not by the independent checks: a panel phase bug, named so.
    if (problems.empty()) problems.push_back("quality_check");
    j.begin_array("problems");
    for (const std::string& p : problems) j.value(nullptr, p);
    j.end_array();
    j.value("vertices", i < pm.panels.size() ? static_cast<int>(pm.panels[i].size()) : 0);
    if (i < pm.issues.size() && pm.issues[i].spike_vertices > 0) j.value("spike_vertices", pm.issues[i].spike_vertices);
    j.end_object();
  }
  j.end_array();
}

const char* status(const RemeshRun& run) {
  const PanelMesh& pm = run.remesher.panels();
  if (pm.num_panels() == 0) return "no panels";
  return all_panels_valid(pm, run.quality) ? "valid" : "some panels invalid";
}

}  // namespace

bool all_panels_valid(const PanelMesh& panels, const QualityReport& quality) {
  return panels.num_panels() > 0 && panels.num_invalid() == 0 && quality.invalid_panels == 0;
}

std::vector<std::string> panel_problems(const PanelIssues& issues) {
  std::vector<std::string> problems;
  if (issues.not_simple) problems.push_back("not_simple");
  if (issues.flipped) problems.push_back("flipped");
  if (issues.not_star) problems.push_back("not_star");
  if (issues.spike_vertices > 0) problems.push_back("spike");
  if (issues.too_few_vertices) problems.push_back("too_few_vertices");
  if (issues.not_disk) problems.push_back("not_disk");
  return problems;
}

std::string remesh_report_json(const RemeshRun& run) {
  const Remesher& r = run.remesher;
  const RemeshParams& p = r.params();
  const PanelMesh& pm = r.panels();
  const EnergyTerms e = r.energy();
  JsonWriter j;
  j.begin_object();
  j.value("input", run.input.path);
  j.value("input_vertices", run.input.raw.mesh.num_vertices());
  j.value("input_triangles", run.input.raw.mesh.num_faces());
  j.value("mesh_vertices", r.mesh().num_vertices());
  j.value("triangles", r.mesh().num_faces());
  j.value("components", r.topology().num_components);
  j.begin_array("cleanup");
  for (const std::string& m : run.input.clean.report.messages()) j.value(nullptr, m);
  j.end_array();

  j.value("status", status(run));
  j.value("requested_panels", run.requested_panels);
  j.value("panels", run.quality.panels);
  j.value("vertices", run.quality.vertices);
  write_quality(j, run.quality);
  // The panel phase's own verdict; `invalid_panels` above is the independent measurement.
  j.value("invalid_panels_flagged", pm.num_invalid());
  write_invalid(j, pm, run.quality);

  j.value("seed", static_cast<std::uint64_t>(p.seed));
  j.value("seeding", run.seeding);
  j.begin_object("weights");
  j.value("euclidean", p.weights.euclidean).value("l2", p.weights.l2).value("l21", p.weights.l21);
  j.value("density", p.weights.density).value("boundary", p.weights.boundary);
  j.end_object();
  j.value("density_file", !p.density.empty());
  j.value("single_point_nodes", p.single_point_nodes);
  j.value("optimize_planes", p.optimize_planes);
  j.begin_object("iterations");
  j.value("lloyd", r.lloyd_iterations_done()).value("panel_rounds", r.panel_rounds_done());
  j.value("lloyd_limit", p.lloyd_iterations).value("panel_rounds_limit", p.panel_rounds);
  j.end_object();
  j.value("converged", r.converged());
  j.value("teleports", r.teleports_done());
  j.value("expected_cluster_diameter", r.metric().diameter());
  j.begin_object("energy");
  j.value("euclidean", e.euclidean).value("l2", e.l2).value("l21", e.l21).value("density", e.density);
  j.value("total", e.total());
  j.end_object();

  const RemeshTimings& t = run.timings;
  j.begin_object("timings_s");
  j.value("prepare", t.prepare).value("cluster", t.cluster).value("panels", t.panels);
  j.value("quality", t.quality).value("total", t.total);
  j.end_object();
  j.end_object();
  return j.str();
}

std::string panels_obj_comment(const RemeshRun& run) {
  return std::string("flatfacet ") + kVersion + " remesh\n" + "input: " + run.input.path + "\n" +
         "panels: " + std::to_string(run.quality.panels) + " (requested " + std::to_string(run.requested_panels) +
         "), vertices: " + std::to_string(run.quality.vertices) +
         ", seed: " + std::to_string(run.remesher.params().seed) +
         ", invalid panels: " + std::to_string(run.quality.invalid_panels) + "\n";
}

std::string remesh_summary_line(const RemeshRun& run) {
  const QualityReport& q = run.quality;
  const PanelMesh& pm = run.remesher.panels();
  std::string validity = status(run);
  if (validity == std::string("some panels invalid"))
    validity = std::to_string(std::max(q.invalid_panels, pm.num_invalid())) + " invalid";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%d panels (%d requested), %d vertices, %s; planarity %.3g, hausdorff %.3g, topology %s, "
                "valence-3 %.1f%%, %.2f s\n",
                q.panels, run.requested_panels, q.vertices, validity.c_str(), q.max_planarity, q.hausdorff,
                q.topology_preserved ? "preserved" : "changed", 100.0 * q.valence3_share, run.timings.total);
  return buf;
}

}  // namespace ff::cli
