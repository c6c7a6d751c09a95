#pragma once
// One designer's session in the browser: the loaded mesh, the parameters and the Remesher,
// behind calls that never throw. Plain C++ over the core (bindings.cpp only converts types
// for JavaScript), so everything the page can do is also callable from native code.
//
// Every failing call leaves the previous mesh, parameters and result as they were, and
// answers with a Status JSON {"ok": false, "message": "..."} naming the problem. The one
// exception that can still escape is running out of memory in the typed-array getters (a
// std::bad_alloc from a copy); the page treats that, and any wasm trap, as a crashed solver.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/fabricate/fabrication_params_json.h"
#include "core/mesh/clean.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "core/util/json_writer.h"

namespace ff::wasm {

class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // MeshInfo JSON (wasm/flatfacet.d.ts).
  std::string load_mesh(const std::string& name, std::string_view bytes);
  std::string load_arrays(const std::string& name, const std::vector<double>& positions,
                          const std::vector<std::uint32_t>& indices);
  std::string load_shape(const std::string& name, int triangles);
  // NURBS surfaces (SurfaceSet JSON, core/prepare/nurbs_json.h) tessellated in the core, plus a
  // triangle soup (meshes, render meshes of trimmed faces) loaded with them, welded within the
  // set's weldTolerance (wasm/session_surface.cpp). MeshInfo JSON with "edgeLength" and
  // "surfaces": [{"name", "triangles", "samplesU", "samplesV", "seamWelded"}].
  std::string load_surfaces(const std::string& name, const std::string& surfaces_json,
                            const std::vector<double>& positions, const std::vector<std::uint32_t>& indices);
  // After a load (wasm/session_prepare.cpp), and again whenever the panel count outgrows the
  // mesh: from the mesh as loaded, subdivide it as a control mesh `subdivide` levels (Loop on
  // triangles, else Catmull-Clark on the file's polygons), then remesh it to the resolution
  // `panels` need (core/prepare/prepare.h: refined below 30 triangles per panel, else
  // untouched bit for bit), or to `edge_length` when > 0 (0: automatic). refine_below: the
  // triangles per panel below which it refines (PrepareOptions::refine_triangles_per_panel, 20
  // to 50; 0: the core's, 30; 20 for designs saved before the 30). refine_rounds: the
  // remeshing rounds of a refinement below 20 per panel (PrepareOptions::refine_rounds, 1 to
  // 10; 0: the core's, 5; 10 for designs saved before the 5). MeshInfo JSON whose "prepared"
  // lists what was done and why; on failure a Status and the mesh stays as it was.
  std::string prepare(int panels, int subdivide, double edge_length, int refine_below, int refine_rounds);
  // The mesh as loaded again, neither subdivided nor prepared (a design saved before
  // preparations were recorded was made on it); otherwise as prepare().
  std::string prepare_as_loaded();
  // What was attached to the mesh before the last prepare(), carried to the mesh now
  // (core/prepare/mesh_transfer.h): per-vertex values by closest point, triangle ids by
  // nearest centroid. Empty when refused (wrong length, an id out of range, no mesh before).
  // The mesh before is kept only for this carrying: the next set_density or set_params that
  // is accepted, or step(), drops it (as does a load), so then both refuse.
  std::vector<double> transfer_field(const std::vector<double>& values) const;
  std::vector<std::int32_t> remap_faces(const std::vector<std::int32_t>& faces) const;
  // How the next loads repair the mesh (wasm/session_repair.cpp, core/mesh/clean.h): fill
  // holes of at most `fill_holes` edges (0 = off, at most 500) and, with `largest_part`, cut
  // a mesh with non-manifold edges there and keep only its largest part (otherwise such a
  // load, or one with a part far from the rest, fails with a Status naming the problem and
  // "largestPart": {"faces", "of"}). Status JSON; the mesh loaded already stays as it is.
  std::string set_repair(int fill_holes, bool largest_part);
  // Status JSON. Warm-starts a solve under way or finished (Remesher::set_params). The
  // density field (set_density) stays as it is.
  std::string set_params(const std::string& params_json);
  // Density per vertex of the cleaned mesh (wasm/session_density.cpp): higher = smaller
  // panels; empty = uniform. Status JSON: refused (and nothing changed) unless there is one
  // finite value > 0 per vertex. Warm-starts like set_params; the same field is a no-op. A
  // new mesh drops it.
  std::string set_density(const std::vector<double>& density);
  // Progress JSON.
  std::string step();
  bool done() const;
  // Drops the solve: the next step() starts cold from the loaded mesh with the current
  // parameters (what a new Session would do), without reading the mesh again.
  void reset_solve();

  std::vector<float> input_positions() const;
  std::vector<std::uint32_t> input_indices() const;
  std::vector<std::int32_t> cluster_ids() const;
  std::vector<double> panel_positions() const;
  std::vector<std::uint32_t> panel_offsets() const;
  std::vector<std::uint32_t> panel_indices() const;
  std::vector<std::uint32_t> panel_triangles() const;
  std::vector<std::uint32_t> panel_triangle_ids() const;
  // Per cleaned triangle: its panel (index into panel_offsets' panels), -1 for none. One
  // selected panel on the page names both its triangle (edits) and its panel (thickness).
  std::vector<std::int32_t> face_panels() const;
  // The density expression evaluated per vertex of the cleaned mesh, as the solver multiplies
  // it with the paint (session_density.cpp); empty for no expression or one it refuses.
  std::vector<double> expression_density(const std::string& expression) const;
  std::vector<double> corner_positions() const;
  std::vector<double> corner_planarity() const;
  // Per panel: how far it is from the design near it (core/quality/panel_deviation.h).
  std::vector<double> panel_deviation() const;
  std::string problems();
  std::string report_json();
  std::string obj_text();  // empty without panels

  // Fabrication (wasm/session_fabrication.cpp; wasm/flatfacet.d.ts, FabricationParams) reads
  // the panels last kept: keep_panels() copies the current ones when a solve's result is
  // shown, so a later solve, under way or cancelled half-way, does not change what is
  // fabricated (the page shows the last finished design then). They stay until the next
  // keep_panels(), through loads too (the worker tells which design they are of).
  void keep_panels();
  // Status JSON; the settings stay as they were on failure.
  std::string set_fabrication(const std::string& json);
  // Texts (a Status JSON on failure: it starts with '{', which CSV, SVG, DXF and OBJ never do;
  // partsJson's failure has "ok": false). Empty parts lists without kept panels.
  std::string parts_csv() const;
  std::string parts_json() const;
  std::string sheets_svg() const;
  std::string sheets_dxf() const;
  std::string solid_obj() const;  // needs a thickness
  // {"ok", "message", "sheets", "materialUse"}: the cut-sheet packing's numbers.
  std::string sheet_stats() const;
  // Inner-face corners, xyz per panel corner in the order of panelIndices (so panelOffsets
  // applies), in mesh units; empty without panels or thickness.
  std::vector<double> inner_positions() const;
  // {"ok", "message", "units", "thickness", "maxSpread", "nodes": [{"vertex", "position"
  // (mesh units), "spread" (designer's units), "panels"}]}.
  std::string spread_nodes() const;

  // Per-panel edits (wasm/session_edits.cpp; they arrive in set_params' `edits`). The panel
  // (cluster) of a cleaned triangle, -1 when out of range or before clustering; a face inside
  // a panel (to name it in an edit), -1 when out of range; the locked panels, sorted; the
  // number of panels now (the requested count plus splits minus merges; 0 before clustering).
  int panel_of_face(int face) const;
  int panel_face(int panel) const;
  std::vector<std::int32_t> locked_panels() const;
  int panel_count() const;

 private:
  struct Timings {
    double cluster = 0.0, panels = 0.0, quality = 0.0;
  };
  // source_polygon: the file polygon of each raw triangle (empty: every triangle its own).
  std::string load(const std::string& name, TriMesh raw, int input_triangles, const CleanOptions& clean_options = {},
                   const std::vector<int>& source_polygon = {});
  std::string mesh_info_json() const;
  void write_repair_json(JsonWriter& j) const;  // MeshInfo's "repair" (session_repair.cpp)
  // Designing on the prepared mesh has begun: the mesh before is no longer carried from
  // (session_prepare.cpp).
  void forget_mesh_before();
  // prepare()'s and prepare_as_loaded()'s end: `mesh` on show, the mesh before kept to carry
  // from; `is_original`: `mesh` is original_ unchanged.
  std::string adopt_mesh(TriMesh mesh, std::vector<std::string> notes, bool is_original);
  const QualityReport* quality();
  void forget_result();
  // Edits (session_edits.cpp): what set_params compares to tell an edit from a new solve
  // (the parameters' JSON without `edits`, canonical, with `panels` as the target a count
  // that is no change stands for: kept_target), and the edit-only path.
  static std::string solve_key(const std::string& params_json, int panels);
  int kept_target(const RemeshParams& params) const;
  bool apply_edits_only(const std::string& key, const RemeshParams& params);

  std::string name_;
  TriMesh mesh_;      // cleaned, then prepared
  TriMesh original_;  // cleaned as loaded: what every prepare() starts from
  TriMesh previous_;  // the mesh before the last prepare(), until carrying ends (forget_mesh_before)
  MeshTopology topology_;
  std::vector<std::string> cleanup_;   // what clean-up repaired, one sentence each
  CleanOptions repair_;                // set_repair(): how loads repair the mesh
  CleanReport clean_report_;           // of the loaded mesh
  // The loaded surface passing through itself (surface_crossings of original_): told on load
  // (MeshInfo's selfCrossings), and given to each solve's report while mesh_ is original_.
  SurfaceCrossings original_crossings_;
  bool mesh_is_original_ = false;
  std::vector<std::string> prepared_notes_;  // what prepare() did and why
  std::vector<int> face_polygon_;     // per triangle of original_: its polygon in the file
  int input_triangles_ = 0;
  RemeshParams params_;
  FabricationSettings fabrication_;
  PanelMesh kept_panels_;  // keep_panels(): what fabrication reads
  // The last cut-sheet packing and what it was packed from (session_fabrication.cpp): one
  // fabrication request asks for the SVG, the DXF and the stats of the same layout.
  struct SheetCache {
    std::vector<PanelOutline> outlines;
    SheetOptions sheet;
    SheetLayout layout;
    bool valid = false;
  };
  mutable SheetCache sheet_cache_;
  const SheetLayout& sheet_layout(const std::vector<PanelOutline>& outlines) const;
  std::unique_ptr<Remesher> remesher_;
  std::optional<QualityReport> quality_;  // of the current panels, measured on demand
  Timings timings_;                       // of the solve since the last load or parameter change
  double prepare_seconds_ = 0.0;          // cleaning + topology of the loaded mesh
  std::string solve_key_;                 // solve_key() of the last accepted parameters
};

}  // namespace ff::wasm
