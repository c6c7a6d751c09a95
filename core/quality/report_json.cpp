#include "core/quality/report_json.h"

#include <algorithm>
#include <set>
#include <utility>

#include "core/util/short_number.h"

namespace ff {

bool all_panels_valid(const PanelMesh& panels, const QualityReport& quality) {
  return panels.num_panels() > 0 && panels.num_invalid() == 0 && quality.invalid_panels == 0;
}

bool result_valid(const PanelMesh& panels, const QualityReport& quality) {
  return all_panels_valid(panels, quality) && quality.topology_preserved;
}

const char* panels_status(const PanelMesh& panels, const QualityReport& quality) {
  if (panels.num_panels() == 0) return "no panels";
  if (!all_panels_valid(panels, quality)) return "some panels invalid";
  return quality.topology_preserved ? "valid" : "topology changed";
}

std::string topology_phrase(const QualityReport& q) {
  if (q.topology_preserved) return "";
  std::string out = "the panels do not keep the surface's topology (";
  if (!q.oriented_manifold) return out + "they are not an oriented 2-manifold)";
  return out + "Euler characteristic " + std::to_string(q.euler_in) + " -> " + std::to_string(q.euler_out) +
         ", boundary loops " + std::to_string(q.boundary_loops_in) + " -> " + std::to_string(q.boundary_loops_out) + ")";
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

namespace {

// A point as an array of its three coordinates.
void write_point(JsonWriter& j, const char* key, const Vec3& p) {
  j.begin_array(key);
  for (int k = 0; k < 3; ++k) j.value(nullptr, p[k]);
  j.end_array();
}

}  // namespace

void write_quality_fields(JsonWriter& j, const QualityReport& q) {
  j.value("max_planarity", q.max_planarity);
  j.value("max_planarity_panel", q.max_planarity_panel);
  j.value("planarity_floor", q.planarity_floor);
  j.value("planarity_floor_solve", q.planarity_floor_solve);
  // DESIGN.md 4: `hausdorff` is the two-sided distance (/ bbox diagonal); both halves follow.
  j.value("hausdorff", q.hausdorff);
  j.value("hausdorff_input_to_panels", q.hausdorff_input_to_panels);
  j.value("hausdorff_panels_to_input", q.hausdorff_panels_to_input);
  write_point(j, "hausdorff_worst_point", q.hausdorff_worst_point);
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
  write_point(j, "min_corner_angle_point", q.min_corner_angle_point);
  j.value("min_corner_angle_panel", q.min_corner_angle_panel);
  j.value("min_corner_angle_target_deg", q.min_corner_angle_target_deg);
  j.value("acute_corners", q.acute_corners);
  j.value("concave_panels", q.concave_panels);
  j.value("min_panel_coverage", q.min_panel_coverage);
  j.value("min_panel_coverage_panel", q.min_panel_coverage_panel);
  j.value("min_panel_coverage_cluster", q.min_panel_coverage_cluster);
  j.value("collapsed_panels", q.collapsed_panels);
  // Panels passing through each other: each pair, its deepest point, and the deepest share.
  j.begin_array("crossing_panels");
  for (size_t k = 0; k < q.crossing_pairs.size(); ++k) {
    j.begin_object();
    j.begin_array("panels").value(nullptr, q.crossing_pairs[k][0]).value(nullptr, q.crossing_pairs[k][1]).end_array();
    write_point(j, "point", q.crossing_points[k]);
    j.end_object();
  }
  j.end_array();
  j.value("max_crossing_depth", q.max_crossing_depth);
  j.value("input_crossings", q.input_crossings);
  write_point(j, "input_crossing_point", q.input_crossing_point);
  j.value("input_crossing_places", q.input_crossing_places);
}

std::vector<InvalidPanel> list_invalid_panels(const PanelMesh& pm, const QualityReport& q) {
  std::set<int> ids(q.invalid_panel_ids.begin(), q.invalid_panel_ids.end());
  for (size_t i = 0; i < pm.issues.size(); ++i)
    if (!pm.issues[i].valid()) ids.insert(static_cast<int>(i));
  std::vector<InvalidPanel> out;
  for (const int id : ids) {
    const size_t i = static_cast<size_t>(id);
    InvalidPanel& p = out.emplace_back();
    p.panel = id;
    p.cluster = i < pm.panel_cluster.size() ? pm.panel_cluster[i] : -1;
    if (i < pm.issues.size()) p.problems = panel_problems(pm.issues[i]);
    // Valid by its own flags but not by the independent checks: a panel phase bug, named so
    // (off its plane with every other check passed, or another check failed).
    const bool off_plane = std::binary_search(q.solver_error_panel_ids.begin(), q.solver_error_panel_ids.end(), id);
    if (p.problems.empty()) p.problems.push_back(off_plane ? "off_plane" : "quality_check");
    p.vertices = i < pm.panels.size() ? static_cast<int>(pm.panels[i].size()) : 0;
    p.spike_vertices = i < pm.issues.size() ? pm.issues[i].spike_vertices : 0;
  }
  for (const int c : pm.unbuilt_clusters) {
    InvalidPanel& p = out.emplace_back();
    p.cluster = c;
    p.problems.push_back("unbuilt");
  }
  return out;
}

void write_invalid_panels(JsonWriter& j, const PanelMesh& pm, const QualityReport& q) {
  j.begin_array("invalid");
  for (const InvalidPanel& p : list_invalid_panels(pm, q)) {
    j.begin_object();
    j.value("panel", p.panel);
    j.value("cluster", p.cluster);
    j.begin_array("problems");
    for (const std::string& name : p.problems) j.value(nullptr, name);
    j.end_array();
    j.value("vertices", p.vertices);
    if (p.spike_vertices > 0) j.value("spike_vertices", p.spike_vertices);
    j.end_object();
  }
  j.end_array();
}

std::string invalid_panels_phrase(const PanelMesh& pm, const QualityReport& q) {
  const std::vector<InvalidPanel> invalid = list_invalid_panels(pm, q);
  if (invalid.empty()) return "";
  // Each name once, in panel_problems' order, then the three names list_invalid_panels adds.
  static const char* const kOrder[] = {"not_simple", "flipped",      "not_star",  "spike",         "too_few_vertices",
                                       "not_disk",   "acute_corner", "off_plane", "quality_check", "unbuilt"};
  std::vector<std::pair<std::string, int>> counts;
  for (const char* name : kOrder) counts.emplace_back(name, 0);
  for (const InvalidPanel& p : invalid)
    for (const std::string& name : p.problems)
      for (auto& [known, count] : counts) count += known == name ? 1 : 0;
  counts.erase(std::remove_if(counts.begin(), counts.end(), [](const auto& c) { return c.second == 0; }),
               counts.end());
  std::string out = std::to_string(invalid.size()) + (invalid.size() == 1 ? " panel" : " panels") + " invalid (";
  for (size_t k = 0; k < counts.size(); ++k)
    out += (k > 0 ? ", " : "") + counts[k].first + " " + std::to_string(counts[k].second);
  return out + ")";
}

std::string crossing_phrase(const QualityReport& q) {
  const size_t n = q.crossing_pairs.size();
  if (n == 0) return "";
  std::string pairs;
  for (size_t k = 0; k < n && k < 4; ++k) {
    pairs += (k > 0 ? ", P" : "P") + std::to_string(q.crossing_pairs[k][0] + 1) + " and P" +
             std::to_string(q.crossing_pairs[k][1] + 1);
  }
  if (n > 4) pairs += ", ...";
  std::string out = std::to_string(n) + (n == 1 ? " pair" : " pairs") + " of panels pass through each other (" + pairs +
                    "; the deepest " + short_number(100.0 * q.max_crossing_depth) +
                    "% of the smaller panel's size into both; --report lists them as crossing_panels): they cannot be "
                    "built as drawn; ";
  if (q.input_crossings > 0) {
    const Vec3& p = q.input_crossing_point;
    return out + "the surface itself passes through itself (" + crossing_where(q.input_crossing_places, p) +
           "), and panels made from it follow it: mend the model there";
  }
  return out + "more panels there, or another --seed or --panels count, may avoid it";
}

std::string planarity_phrase(const QualityReport& q) {
  if (!(q.max_planarity > kPlanarityTarget)) return "";
  std::string out = "the panels as written are flat to " + short_number(q.max_planarity) + " of their size, not " +
                    short_number(kPlanarityTarget);
  // Within kRoundingAllowance of what the doubles allow: the coordinates, not the solve.
  if (q.planarity_floor * kRoundingAllowance >= q.max_planarity)
    return out + ": the coordinates are so far from the origin that their last digit is already " +
           short_number(q.planarity_floor) + " of a panel's size; moved near the origin, the model gives flat panels";
  // The coordinates about the middle of the whole mesh: a far-off part moved it away.
  if (q.planarity_floor_solve * kRoundingAllowance >= q.max_planarity)
    return out + ": a part of the mesh lies so far from the rest that, about the middle of the whole, the "
                 "coordinates' last digit is already " +
           short_number(q.planarity_floor_solve) + " of a panel's size; without the far-off part, the model gives flat panels";
  // Else a vertex whose planes have no common point (closest_point_on_planes' inexact case),
  // which the panel phase counts as a spike: the panel is invalid and listed.
  // Or a panel off its plane that passes every other check: the solver's error.
  const int panel = q.max_planarity_panel;
  out += "; the least flat is panel " + std::to_string(panel);
  if (std::binary_search(q.solver_error_panel_ids.begin(), q.solver_error_panel_ids.end(), panel))
    return out +
           ", an invalid one, off its plane though it passes every other check (an error of the solver: please "
           "report it)";
  const bool invalid = std::binary_search(q.invalid_panel_ids.begin(), q.invalid_panel_ids.end(), panel);
  return out + (invalid ? ", an invalid one (a vertex where its planes do not meet)" : "");
}

}  // namespace ff
