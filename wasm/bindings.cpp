// Embind bindings: JavaScript types in and out of ff::wasm::Session, nothing else. Typed
// arrays are copied both ways (a view into the wasm heap dies when the memory grows).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>
#include <vector>

#include "core/version.h"
#include "wasm/session.h"

namespace {

using emscripten::val;
using ff::wasm::Session;

template <typename T>
val to_typed_array(const std::vector<T>& data, const char* type) {
  // The view aliases the heap only for the duration of the copy made by the constructor.
  return val::global(type).new_(emscripten::typed_memory_view(data.size(), data.data()));
}

template <typename T>
std::vector<T> from_typed_array(const val& array) {
  return emscripten::convertJSArrayToNumberVector<T>(array);
}

std::string load_mesh(Session& s, const std::string& name, const val& bytes) {
  const std::vector<std::uint8_t> data = from_typed_array<std::uint8_t>(bytes);
  return s.load_mesh(name, std::string_view(reinterpret_cast<const char*>(data.data()), data.size()));
}

std::string load_arrays(Session& s, const std::string& name, const val& positions, const val& indices) {
  return s.load_arrays(name, from_typed_array<double>(positions), from_typed_array<std::uint32_t>(indices));
}

std::string load_surfaces(Session& s, const std::string& name, const std::string& json, const val& positions,
                          const val& indices) {
  return s.load_surfaces(name, json, from_typed_array<double>(positions), from_typed_array<std::uint32_t>(indices));
}

std::string version() { return ff::kVersion; }

}  // namespace

EMSCRIPTEN_BINDINGS(flatfacet) {
  emscripten::function("version", &version);
  emscripten::class_<Session>("Session")
      .constructor<>()
      .function("loadMesh", &load_mesh)
      .function("loadArrays", &load_arrays)
      .function("loadShape", &Session::load_shape)
      .function("loadSurfaces", &load_surfaces)
      .function("prepare", &Session::prepare)
      .function("prepareAsLoaded", &Session::prepare_as_loaded)
      .function("setRepair", &Session::set_repair)
      .function(
          "transferField",
          +[](const Session& s, const val& values) {
            return to_typed_array(s.transfer_field(from_typed_array<double>(values)), "Float64Array");
          })
      .function(
          "remapFaces",
          +[](const Session& s, const val& faces) {
            return to_typed_array(s.remap_faces(from_typed_array<std::int32_t>(faces)), "Int32Array");
          })
      .function("setParams", &Session::set_params)
      .function(
          "setDensity",
          +[](Session& s, const val& density) { return s.set_density(from_typed_array<double>(density)); })
      .function("step", &Session::step)
      .function("done", &Session::done)
      .function("resetSolve", &Session::reset_solve)
      .function(
          "inputPositions", +[](const Session& s) { return to_typed_array(s.input_positions(), "Float32Array"); })
      .function(
          "inputIndices", +[](const Session& s) { return to_typed_array(s.input_indices(), "Uint32Array"); })
      .function(
          "clusterIds", +[](const Session& s) { return to_typed_array(s.cluster_ids(), "Int32Array"); })
      .function(
          "panelPositions", +[](const Session& s) { return to_typed_array(s.panel_positions(), "Float64Array"); })
      .function(
          "panelOffsets", +[](const Session& s) { return to_typed_array(s.panel_offsets(), "Uint32Array"); })
      .function(
          "panelIndices", +[](const Session& s) { return to_typed_array(s.panel_indices(), "Uint32Array"); })
      .function(
          "panelTriangles", +[](const Session& s) { return to_typed_array(s.panel_triangles(), "Uint32Array"); })
      .function(
          "panelTriangleIds", +[](const Session& s) { return to_typed_array(s.panel_triangle_ids(), "Uint32Array"); })
      .function(
          "facePanels", +[](const Session& s) { return to_typed_array(s.face_panels(), "Int32Array"); })
      .function(
          "expressionDensity",
          +[](const Session& s, const std::string& e) {
            return to_typed_array(s.expression_density(e), "Float64Array");
          })
      .function(
          "cornerPositions", +[](const Session& s) { return to_typed_array(s.corner_positions(), "Float64Array"); })
      .function(
          "cornerPlanarity", +[](const Session& s) { return to_typed_array(s.corner_planarity(), "Float64Array"); })
      .function(
          "panelDeviation", +[](const Session& s) { return to_typed_array(s.panel_deviation(), "Float64Array"); })
      .function("problems", &Session::problems)
      .function("reportJson", &Session::report_json)
      .function("objText", &Session::obj_text)
      .function("keepPanels", &Session::keep_panels)
      .function("setFabrication", &Session::set_fabrication)
      .function("partsCsv", &Session::parts_csv)
      .function("partsJson", &Session::parts_json)
      .function("sheetsSvg", &Session::sheets_svg)
      .function("sheetsDxf", &Session::sheets_dxf)
      .function("sheetStats", &Session::sheet_stats)
      .function("solidObj", &Session::solid_obj)
      .function(
          "innerPositions", +[](const Session& s) { return to_typed_array(s.inner_positions(), "Float64Array"); })
      .function("spreadNodes", &Session::spread_nodes)
      .function("panelOfFace", &Session::panel_of_face)
      .function("panelFace", &Session::panel_face)
      .function(
          "lockedPanels", +[](const Session& s) { return to_typed_array(s.locked_panels(), "Int32Array"); })
      .function("panelCount", &Session::panel_count);
}
