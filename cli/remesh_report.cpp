#include "cli/remesh_report.h"

#include <algorithm>
#include <cstdio>

#include "cli/commands.h"
#include "core/density/anisotropy.h"
#include "core/panels/panel_export.h"
#include "core/quality/report_json.h"
#include "core/util/json_writer.h"

namespace ff::cli {

namespace {

const char* status(const RemeshRun& run) { return panels_status(run.remesher.panels(), run.quality); }

// Only when --subdivide was given, so other reports stay byte-identical.
void write_subdivision(JsonWriter& j, const SubdivisionInfo& s) {
  if (s.levels <= 0) return;
  j.begin_object("subdivision");
  j.value("scheme", s.scheme).value("levels", s.levels).value("crease_angle_deg", s.crease_angle_deg);
  j.value("control_vertices", s.control_vertices).value("control_faces", s.control_faces);
  j.value("crease_edges", s.crease_edges).value("triangles", s.triangles);
  j.end_object();
}

// What clean-up repaired beyond "cleanup"'s sentences, as numbers, and what was asked.
void write_repair(JsonWriter& j, const LoadedInput& in) {
  const CleanReport& c = in.clean.report;
  j.begin_object("repair");
  j.value("welded_vertices", c.welded_vertices);
  j.value("degenerate_faces_dropped", c.degenerate_faces_dropped).value("duplicate_faces_dropped", c.duplicate_faces_dropped);
  j.value("slivers_removed", c.slivers_removed).value("zero_area_faces", c.zero_area_faces);
  j.value("nonmanifold_vertices_split", c.nonmanifold_vertices_split).value("faces_flipped", c.faces_flipped);
  j.value("fill_holes_max_edges", in.repair.fill_holes_max_edges);
  j.value("holes_filled", c.holes_filled).value("hole_faces_added", c.hole_faces_added);
  j.value("largest_part", in.repair.largest_manifold_part);
  j.value("nonmanifold_edges_cut", c.nonmanifold_edges_cut).value("faces_outside_part", c.faces_outside_part);
  j.value("parts_dropped", c.parts_dropped);
  j.end_object();
}

}  // namespace

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
  write_repair(j, run.input);
  write_subdivision(j, run.input.subdivision);

  const PrepareReport& prep = run.prepare;
  j.begin_object("prepare");
  j.value("applied", prep.applied);
  j.value("triangles_in", prep.triangles_in).value("triangles_out", prep.triangles_out);
  j.value("target_edge", prep.target_edge);
  // The prepared surface's two-sided distance to the input: / bbox diagonal like the top-level
  // "hausdorff", and absolute (both 0 when not applied).
  j.value("hausdorff", prep.distance_relative).value("hausdorff_absolute", prep.distance);
  j.begin_array("messages");
  for (const std::string& m : prep.messages) j.value(nullptr, m);
  j.end_array();
  j.end_object();

  j.value("status", status(run));
  j.value("requested_panels", run.requested_panels);
  j.value("panels", run.quality.panels);
  j.value("vertices", run.quality.vertices);
  write_quality_fields(j, run.quality);
  // The panel phase's own verdict; `invalid_panels` above is the independent measurement.
  j.value("invalid_panels_flagged", pm.num_invalid());
  write_invalid_panels(j, pm, run.quality);

  j.value("seed", static_cast<std::uint64_t>(p.seed));
  j.value("seeding", run.seeding);
  j.begin_object("weights");
  j.value("euclidean", p.weights.euclidean).value("l2", p.weights.l2).value("l21", p.weights.l21);
  j.value("density", p.weights.density).value("boundary", p.weights.boundary);
  j.end_object();
  j.value("density_file", !p.density.empty());
  // Only when set, so runs without them keep their reports byte for byte.
  if (!p.density_expression.empty()) j.value("density_expression", p.density_expression);
  if (p.anisotropy.active()) {
    j.begin_object("anisotropy");
    j.value("direction", anisotropy_direction_name(p.anisotropy)).value("stretch", p.anisotropy.stretch);
    if (p.anisotropy.direction == AnisotropyDirection::Expression) {
      // Faces the expression leaves isotropic (zero, or along the normal).
      j.value("expression", p.anisotropy.expression);
      j.value("isotropic_faces", count_isotropic_faces(run.remesher.metric().faces().stretch, p.anisotropy));
    }
    j.end_object();
  }
  j.value("single_point_nodes", p.single_point_nodes);
  j.value("optimize_planes", p.optimize_planes);
  j.value("glass", p.glass);
  j.value("min_angle_deg", p.min_corner_angle_deg);
  j.value("coplanar_angle_deg", p.coplanar_angle_deg);
  j.begin_object("iterations");
  j.value("lloyd", r.lloyd_iterations_done()).value("panel_rounds", r.panel_rounds_done());
  j.value("lloyd_limit", p.lloyd_iterations).value("panel_rounds_limit", p.panel_rounds);
  // Solves from a new seeding made after the first (RemeshParams::retries); the counts above
  // are the kept solve's.
  j.value("retries", r.retries_done()).value("retries_limit", p.retries);
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
  return ff::panels_obj_comment(run.input.path, run.quality.panels, run.requested_panels, run.quality.vertices,
                                run.remesher.params().seed, run.quality.invalid_panels);
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
