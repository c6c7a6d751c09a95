// Session::prepare: the page's preparation of a loaded mesh (issue 7), the same steps as
// `flatfacet remesh --subdivide N [--edge-length L]` and the automatic resolution of
// --prepare auto (cli/input, cli/remesh_command), so a coarse or control mesh opened on the
// page gets enough triangles for its panels, and the designer reads what was done and why
// (MeshInfo.prepared). Every preparation starts from the mesh as loaded (kept in the
// session), so preparing again for another panel count gives the very mesh that opening at
// that count gives; what was painted or named on the mesh before is carried over by
// transfer_field / remap_faces.
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/topology.h"
#include "core/prepare/mesh_transfer.h"
#include "core/prepare/prepare.h"
#include "core/prepare/subdivision.h"
#include "core/util/error.h"
#include "core/util/with_commas.h"
#include "wasm/guarded.h"
#include "wasm/session.h"

namespace ff::wasm {

namespace {

// The page offers up to 4 levels (each makes 4x the faces); the core's cap on the result's
// size still applies (kMaxSubdivisionTriangles) with its own message.
constexpr int kMaxPageSubdivision = 4;

}  // namespace

std::string Session::prepare(int panels, int subdivide, double edge_length, int refine_below, int refine_rounds) {
  return guarded([&] {
    if (original_.num_faces() == 0) throw InputError("no mesh loaded");
    if (subdivide < 0 || subdivide > kMaxPageSubdivision)
      throw InputError("subdivision levels must be 0 to " + std::to_string(kMaxPageSubdivision) + ", not " +
                       std::to_string(subdivide));
    if (panels < 1) throw InputError("the panel count must be at least 1");
    if (!std::isfinite(edge_length) || edge_length < 0.0)
      throw InputError("the target edge length must be a positive number (or 0: automatic)");
    // Everything is built on copies: a failure leaves the current mesh as it was.
    TriMesh mesh = original_;
    std::vector<std::string> notes;
    if (subdivide > 0) {
      const ControlSubdivision fine = subdivide_control_mesh(original_, face_polygon_, subdivide);
      mesh = clean_mesh(fine.mesh).mesh;
      const bool loop = fine.scheme == SubdivisionScheme::Loop;
      notes.push_back("subdivided " + with_commas(fine.control_faces) + (loop ? " triangles " : " polygons ") +
                      std::to_string(subdivide) + (subdivide == 1 ? " level" : " levels") + " (" +
                      scheme_name(fine.scheme) + ") into " + with_commas(mesh.num_faces()) + " triangles");
    }
    PrepareOptions options;
    options.edge_length = edge_length;
    if (refine_below != 0) options.refine_triangles_per_panel = refine_below;  // checked by the core
    if (refine_rounds != 0) options.refine_rounds = refine_rounds;             // checked by the core
    PreparedSurface prepared = prepare_surface(mesh, panels, {}, options);
    if (subdivide != 0 || prepared.report.applied)
      for (const std::string& m : prepared.report.messages) notes.push_back(m);
    return adopt_mesh(std::move(prepared.mesh), std::move(notes), subdivide == 0 && !prepared.report.applied);
  });
}

std::string Session::prepare_as_loaded() {
  return guarded([&] {
    if (original_.num_faces() == 0) throw InputError("no mesh loaded");
    return adopt_mesh(original_, {}, true);
  });
}

std::string Session::adopt_mesh(TriMesh mesh, std::vector<std::string> notes, bool is_original) {
  // Even a mesh left as loaded replaces the current one: the session then holds no solve
  // (as after a load) and the transfers below carry from the mesh before.
  MeshTopology topology = build_topology(mesh);
  // The mesh before: what transfer_field and remap_faces carry from.
  previous_ = std::move(mesh_);
  mesh_ = std::move(mesh);
  topology_ = std::move(topology);
  prepared_notes_ = std::move(notes);
  mesh_is_original_ = is_original;
  params_.density.clear();
  remesher_.reset();
  forget_result();
  return mesh_info_json();
}

// Up to three meshes live in a session (as loaded, before, now); the one before is the
// largest when a prepare refined it, and the page carries its paint and edits right after
// prepare(), before anything else.
void Session::forget_mesh_before() { previous_ = TriMesh{}; }

std::vector<double> Session::transfer_field(const std::vector<double>& values) const {
  try {
    return transfer_vertex_values(previous_, values, mesh_);
  } catch (const std::exception&) {
    return {};  // the page checks the length: one value per vertex, or a refusal
  }
}

std::vector<std::int32_t> Session::remap_faces(const std::vector<std::int32_t>& faces) const {
  try {
    if (previous_.num_faces() == 0) return {};
    const std::vector<int> ids(faces.begin(), faces.end());
    const std::vector<int> mapped = nearest_faces_by_centroid(previous_, ids, mesh_);
    return std::vector<std::int32_t>(mapped.begin(), mapped.end());
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace ff::wasm
