// Session::prepare: the page's preparation of a loaded mesh (issue 7), the same steps as
// `flatfacet remesh --subdivide N` and the automatic resolution of --prepare auto (cli/input,
// cli/remesh_command), so a coarse or control mesh opened on the page gets enough triangles
// for its panels, and the designer reads what was done and why (MeshInfo.prepared).
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/topology.h"
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

std::string Session::prepare(int panels, int subdivide) {
  return guarded([&] {
    if (mesh_.num_faces() == 0) throw InputError("no mesh loaded");
    if (prepared_) throw InputError("the mesh is already prepared: open it again to prepare it differently");
    if (subdivide < 0 || subdivide > kMaxPageSubdivision)
      throw InputError("subdivision levels must be 0 to " + std::to_string(kMaxPageSubdivision) + ", not " +
                       std::to_string(subdivide));
    if (panels < 1) throw InputError("the panel count must be at least 1");
    // Everything is built on copies: a failure leaves the loaded mesh as it was.
    TriMesh mesh = mesh_;
    std::vector<std::string> notes;
    if (subdivide > 0) {
      const ControlSubdivision fine = subdivide_control_mesh(mesh_, face_polygon_, subdivide);
      mesh = clean_mesh(fine.mesh).mesh;
      const bool loop = fine.scheme == SubdivisionScheme::Loop;
      notes.push_back("subdivided " + with_commas(fine.control_faces) + (loop ? " triangles " : " polygons ") +
                      std::to_string(subdivide) + (subdivide == 1 ? " level" : " levels") + " (" +
                      scheme_name(fine.scheme) + ") into " + with_commas(mesh.num_faces()) + " triangles");
    }
    PreparedSurface prepared = prepare_surface(mesh, panels, {});
    for (const std::string& m : prepared.report.messages) notes.push_back(m);
    if (subdivide == 0 && !prepared.report.applied) return mesh_info_json();  // nothing to do: as loaded
    MeshTopology topology = build_topology(prepared.mesh);
    mesh_ = std::move(prepared.mesh);
    topology_ = std::move(topology);
    face_polygon_.clear();
    prepared_ = true;
    prepared_notes_ = std::move(notes);
    params_.density.clear();
    remesher_.reset();
    forget_result();
    return mesh_info_json();
  });
}

}  // namespace ff::wasm
