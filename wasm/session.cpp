#include "wasm/session.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <new>

#include "core/fabricate/parts_list.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/poly_mesh.h"
#include "core/panels/panel_crossings.h"
#include "core/panels/panel_export.h"
#include "core/quality/report_json.h"
#include "core/remesh_params_json.h"
#include "core/shapes/example_shapes.h"
#include "core/util/error.h"
#include "core/util/json_writer.h"
#include "wasm/guarded.h"
#include "wasm/mesh_arrays.h"

namespace ff::wasm {

namespace {

using Clock = std::chrono::steady_clock;

// The most self-crossing pairs the page marks (MeshInfo.selfCrossingPoints).
constexpr size_t kMarkedSelfCrossings = 2000;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Total area of the panel polygons (Newell), in mesh units squared: what the parts list's
// total must equal, computed here independently of it.
double total_panel_area(const PanelMesh& pm) {
  double total = 0.0;
  for (const std::vector<int>& panel : pm.panels) {
    Vec3 twice = Vec3::Zero();
    for (size_t i = 0; i < panel.size(); ++i)
      twice += pm.vertices[static_cast<size_t>(panel[i])].cross(
          pm.vertices[static_cast<size_t>(panel[(i + 1) % panel.size()])]);
    total += 0.5 * twice.norm();
  }
  return total;
}

// The page's stage names (wasm/flatfacet.d.ts, StageName).
const char* display_stage(Stage stage) {
  switch (stage) {
    case Stage::Seeding:
      return "Seeding";
    case Stage::Lloyd:
      return "Lloyd";
    case Stage::Panels:
      return "Panels";
    case Stage::Optimize:
      return "Optimize";
    case Stage::Done:
      break;
  }
  return "Done";
}

}  // namespace

Session::Session() = default;
Session::~Session() = default;

std::string Session::load(const std::string& name, TriMesh raw, int input_triangles, const CleanOptions& clean_options,
                          const std::vector<int>& source_polygon) {
  const auto t0 = Clock::now();
  CleanOptions options = clean_options;
  options.fill_holes_max_edges = repair_.fill_holes_max_edges;
  options.largest_manifold_part = repair_.largest_manifold_part;
  CleanMesh clean = clean_mesh(raw, options);
  MeshTopology topology = build_topology(clean.mesh);
  // The file's polygon of each cleaned triangle (a subdivision's control faces, prepare()).
  std::vector<int> face_polygon = cleaned_face_polygons(clean.face_source, source_polygon);
  SurfaceCrossings crossings = surface_crossings(clean.mesh);
  // The copies too (running out of memory in one, a large mesh's second copy, is a refusal that
  // must leave the previous design whole), then replace it by moves and clears.
  TriMesh original = clean.mesh;
  std::vector<std::string> cleanup = clean.report.messages();
  std::string new_name = name;
  name_ = std::move(new_name);
  mesh_ = std::move(clean.mesh);
  original_ = std::move(original);
  forget_mesh_before();
  topology_ = std::move(topology);
  face_polygon_ = std::move(face_polygon);
  input_triangles_ = input_triangles;
  prepared_notes_.clear();
  cleanup_ = std::move(cleanup);
  clean_report_ = clean.report;
  original_crossings_ = std::move(crossings);
  mesh_is_original_ = true;
  params_.density.clear();  // per vertex of the previous mesh
  remesher_.reset();
  forget_result();
  prepare_seconds_ = seconds_since(t0);
  return mesh_info_json();
}

std::string Session::mesh_info_json() const {
  const int euler = euler_characteristic(mesh_, topology_);
  const int loops = static_cast<int>(topology_.boundary_loops.size());
  JsonWriter j;
  j.begin_object().value("ok", true).value("message", "").value("name", name_);
  j.value("vertices", mesh_.num_vertices()).value("triangles", mesh_.num_faces());
  j.value("inputTriangles", input_triangles_).value("components", topology_.num_components);
  j.value("boundaryLoops", loops).value("euler", euler);
  // Orientable surfaces: chi = 2 c - 2 g - b.
  j.value("genus", (2 * topology_.num_components - euler - loops) / 2);
  j.value("bboxDiagonal", bbox_diagonal(mesh_));
  j.value("selfCrossings", original_crossings_.count());
  j.value("selfCrossingPlaces", original_crossings_.places);
  j.begin_array("selfCrossingPoint");
  const Vec3 point = original_crossings_.first_point();
  for (int k = 0; k < 3; ++k) j.value(nullptr, point[k]);
  j.end_array();
  // Every pair's point (x y z ...), for the view's markers: the first alone hid where else the
  // surface crosses itself. At most kMarkedSelfCrossings of them (a mesh folded onto itself
  // can have many thousands, and one marker per pair says no more there).
  j.begin_array("selfCrossingPoints");
  // Not checked (count -1): a partial list, not sent.
  const size_t marked =
      original_crossings_.checked ? std::min(original_crossings_.pairs.size(), kMarkedSelfCrossings) : size_t{0};
  for (size_t i = 0; i < marked; ++i)
    for (int k = 0; k < 3; ++k) j.value(nullptr, original_crossings_.pairs[i].point[k]);
  j.end_array();
  j.begin_array("cleanup");
  for (const std::string& m : cleanup_) j.value(nullptr, m);
  j.end_array();
  write_repair_json(j);
  j.begin_array("prepared");
  for (const std::string& m : prepared_notes_) j.value(nullptr, m);
  j.end_array().end_object();
  return j.str();
}

std::string Session::load_mesh(const std::string& name, std::string_view bytes) {
  return guarded([&] {
    RawMesh raw;
    try {
      raw = read_mesh(bytes, name);
    } catch (const InputError& e) {
      // The page shows the message: name the file, unless the reader already did.
      if (std::string(e.what()).find(name) != std::string::npos) throw;
      throw InputError(name + ": " + e.what());
    }
    const int triangles = raw.mesh.num_faces();
    return load(name, std::move(raw.mesh), triangles, {}, raw.source_polygon);
  });
}

std::string Session::load_arrays(const std::string& name, const std::vector<double>& positions,
                                 const std::vector<std::uint32_t>& indices) {
  return guarded([&] {
    TriMesh mesh = mesh_from_arrays(name + ": ", positions, indices);
    const int triangles = mesh.num_faces();
    return load(name, std::move(mesh), triangles);
  });
}

std::string Session::load_shape(const std::string& name, int triangles) {
  return guarded([&] {
    TriMesh mesh = make_example_shape(name, triangles);
    const int count = mesh.num_faces();
    return load(name, std::move(mesh), count);
  });
}

std::string Session::set_params(const std::string& params_json) {
  return guarded([&] {
    RemeshParams params = remesh_params_from_json(params_json);
    params.make_panels = true;
    params.density = params_.density;  // set apart (set_density)
    params.panels = kept_target(params);
    // Only the edit list changed: edit the design in place (undo / redo replay, session_edits.cpp).
    const std::string key = solve_key(params_json, params.panels);
    if (apply_edits_only(key, params)) {
      forget_mesh_before();
      return status_json(true, "");
    }
    if (remesher_) {
      const bool mid_solve = !remesher_->done();
      remesher_->set_params(params);  // throws and keeps everything on bad parameters
      // A change during a solve continues it: its time so far still counts.
      if (mid_solve)
        quality_.reset();
      else
        forget_result();
    } else if (mesh_.num_faces() > 0) {
      // Build now, so a panel count the mesh cannot take is refused here, not at step().
      remesher_ = std::make_unique<Remesher>(mesh_, params);
      forget_result();
    }
    params_ = params;
    solve_key_ = key;
    forget_mesh_before();
    return status_json(true, "");
  });
}

std::string Session::step() {
  return guarded([&] {
    if (mesh_.num_faces() == 0) throw InputError("no mesh loaded");
    forget_mesh_before();
    if (!remesher_) remesher_ = std::make_unique<Remesher>(mesh_, params_);
    const Stage stage = remesher_->progress().stage;
    const auto t0 = Clock::now();
    const Progress p = remesher_->step();
    (stage == Stage::Seeding || stage == Stage::Lloyd ? timings_.cluster : timings_.panels) += seconds_since(t0);
    quality_.reset();
    JsonWriter j;
    j.begin_object().value("ok", true).value("message", "");
    j.value("stage", display_stage(p.stage)).value("iteration", p.iteration).value("of", p.of);
    j.value("energy", p.energy).value("invalidPanels", p.invalid_panels);
    j.value("done", remesher_->done()).value("panelRounds", remesher_->panel_rounds_done());
    j.value("attempt", remesher_->retries_done() + 1).value("attempts", remesher_->params().retries + 1);
    j.value("needleRounds", p.needle_rounds);
    j.end_object();
    return j.str();
  });
}

bool Session::done() const { return remesher_ && remesher_->done(); }

void Session::forget_result() {
  quality_.reset();
  timings_ = Timings{};
}

const QualityReport* Session::quality() {
  if (!remesher_ || remesher_->panels().num_panels() == 0) return nullptr;
  if (!quality_) {
    const auto t0 = Clock::now();
    QualityOptions options;
    // Mid-solve the page only wants the problems: a coarse Hausdorff is enough then.
    if (!remesher_->done()) options.samples_per_side = 2000;
    options.glass = remesher_->params().glass;  // glass mode's checks, as the CLI's report
    options.min_corner_angle_deg = remesher_->params().min_corner_angle_deg;
    if (mesh_is_original_) options.input_crossings = original_crossings_;
    quality_ = measure_quality(mesh_, topology_, remesher_->panels(), options);
    if (remesher_->done()) timings_.quality = seconds_since(t0);
  }
  return &*quality_;
}

std::string Session::problems() {
  return guarded([&] {
    JsonWriter j;
    j.begin_object().value("ok", true).value("message", "");
    const QualityReport* q = quality();
    const PanelMesh* pm = remesher_ ? &remesher_->panels() : nullptr;
    j.begin_array("spikes");
    if (q)
      for (const int v : q->spike_vertex_ids)
        for (int k = 0; k < 3; ++k) j.value(nullptr, pm->vertices[static_cast<size_t>(v)][k]);
    j.end_array().begin_array("flippedEdges");
    if (q)
      for (const auto& e : q->flipped_edge_vertices)
        for (const int v : e)
          for (int k = 0; k < 3; ++k) j.value(nullptr, pm->vertices[static_cast<size_t>(v)][k]);
    j.end_array().begin_array("acuteCorners");  // glass mode: corners below the minimum angle
    if (q)
      for (const int v : q->acute_corner_vertex_ids)
        for (int k = 0; k < 3; ++k) j.value(nullptr, pm->vertices[static_cast<size_t>(v)][k]);
    // The report's invalid panels (the quality check's and the panel phase's own), so the
    // panels shown red are the ones the report and the status line count.
    j.end_array().begin_array("invalidPanels");
    if (q)
      for (const InvalidPanel& p : list_invalid_panels(*pm, *q))
        if (p.panel >= 0) j.value(nullptr, p.panel);
    j.end_array().begin_array("unbuiltClusters");
    if (pm)
      for (const int c : pm->unbuilt_clusters) j.value(nullptr, c);
    j.end_array().end_object();
    return j.str();
  });
}

std::string Session::report_json() {
  return guarded([&]() -> std::string {
    const QualityReport* q = quality();
    if (!q) return status_json(true, "");
    const Remesher& r = *remesher_;
    const RemeshParams& p = r.params();
    const PanelMesh& pm = r.panels();
    JsonWriter j;
    j.begin_object();
    j.value("ok", true);
    j.value("input", name_).value("mesh_vertices", mesh_.num_vertices()).value("triangles", mesh_.num_faces());
    j.value("components", topology_.num_components);
    j.begin_array("cleanup");
    for (const std::string& m : cleanup_) j.value(nullptr, m);
    j.end_array();
    j.value("status", panels_status(pm, *q));
    j.value("done", r.done());
    j.value("requested_panels", p.panels).value("panels", q->panels).value("vertices", q->vertices);
    j.value("panel_area", total_panel_area(pm));
    write_quality_fields(j, *q);
    j.value("invalid_panels_flagged", pm.num_invalid());
    write_invalid_panels(j, pm, *q);
    j.value("seed", static_cast<std::uint64_t>(p.seed));
    j.value("seeding", p.seeding == SeedingMethod::Random ? "random" : "farthest");
    j.begin_object("weights");
    j.value("euclidean", p.weights.euclidean).value("l2", p.weights.l2).value("l21", p.weights.l21);
    j.value("density", p.weights.density).value("boundary", p.weights.boundary);
    j.end_object();
    j.value("single_point_nodes", p.single_point_nodes).value("optimize_planes", p.optimize_planes);
    // Triangles a direction expression leaves without a direction (zero, along the normal).
    if (p.anisotropy.active() && p.anisotropy.direction == AnisotropyDirection::Expression)
      j.value("anisotropy_isotropic_faces", count_isotropic_faces(r.metric().faces().stretch, p.anisotropy));
    j.begin_object("iterations");
    j.value("lloyd", r.lloyd_iterations_done()).value("panel_rounds", r.panel_rounds_done());
    j.value("lloyd_limit", p.lloyd_iterations).value("panel_rounds_limit", p.panel_rounds);
    j.value("retries", r.retries_done()).value("retries_limit", p.retries);  // as the CLI's report
    j.end_object();
    j.value("expected_cluster_diameter", r.metric().diameter());
    j.begin_object("timings_s");
    j.value("prepare", prepare_seconds_).value("cluster", timings_.cluster).value("panels", timings_.panels);
    j.value("quality", timings_.quality);
    j.value("total", prepare_seconds_ + timings_.cluster + timings_.panels + timings_.quality);
    j.end_object();
    j.end_object();
    return j.str();
  });
}

std::string Session::obj_text() {
  return guarded([&]() -> std::string {
    const QualityReport* q = quality();
    if (!q) return "";
    const std::string comment = panels_obj_comment(name_, q->panels, remesher_->params().panels, q->vertices,
                                                   remesher_->params().seed, q->invalid_panels);
    return panels_obj(remesher_->panels(), comment);
  });
}

void Session::reset_solve() {
  remesher_.reset();
  forget_result();
}

}  // namespace ff::wasm
