#include "core/quality/report_json.h"

#include <set>

namespace ff {

bool all_panels_valid(const PanelMesh& panels, const QualityReport& quality) {
  return panels.num_panels() > 0 && panels.num_invalid() == 0 && quality.invalid_panels == 0;
}

const char* panels_status(const PanelMesh& panels, const QualityReport& quality) {
  if (panels.num_panels() == 0) return "no panels";
  return all_panels_valid(panels, quality) ? "valid" : "some panels invalid";
}

std::vector<std::string> panel_problems(const PanelIssues& issues) {
  std::vector<std::string> problems;
  if (issues.not_simple) problems.push_back("not_simple");
  if (issues.flipped) problems.push_back("flipped");
  if (issues.not_star) problems.push_back("not_star");
  if (issues.spike_vertices > 0) problems.push_back("spike");
  if (issues.too_few_vertices) problems.push_back("too_few_vertices");
  if (issues.not_disk) problems.push_back("not_disk");
  if (issues.acute_corner) problems.push_back("acute_corner");
  return problems;
}

void write_quality_fields(JsonWriter& j, const QualityReport& q) {
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
  j.begin_array("min_corner_angle_point");
  for (int k = 0; k < 3; ++k) j.value(nullptr, q.min_corner_angle_point[k]);
  j.end_array();
  j.value("min_corner_angle_panel", q.min_corner_angle_panel);
  j.value("min_corner_angle_target_deg", q.min_corner_angle_target_deg);
  j.value("acute_corners", q.acute_corners);
  j.value("concave_panels", q.concave_panels);
  j.value("min_panel_coverage", q.min_panel_coverage);
  j.value("min_panel_coverage_panel", q.min_panel_coverage_panel);
  j.value("min_panel_coverage_cluster", q.min_panel_coverage_cluster);
  j.value("collapsed_panels", q.collapsed_panels);
}

void write_invalid_panels(JsonWriter& j, const PanelMesh& pm, const QualityReport& q) {
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
  // Clusters that could not become a panel (no outline: not a disk, too few corners).
  for (const int c : pm.unbuilt_clusters) {
    j.begin_object();
    j.value("panel", -1).value("cluster", c);
    j.begin_array("problems").value(nullptr, "unbuilt").end_array();
    j.value("vertices", 0);
    j.end_object();
  }
  j.end_array();
}

}  // namespace ff
