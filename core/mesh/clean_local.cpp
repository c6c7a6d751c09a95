#include "core/mesh/clean_local.h"

#include "core/mesh/fill_holes.h"
#include "core/mesh/half_edges.h"
#include "core/mesh/orient.h"
#include "core/mesh/slivers.h"

namespace ff::detail {

namespace {

bool has_sliver(const TriMesh& mesh) {
  const double diag = bbox_diagonal(mesh);
  for (const Triangle& t : mesh.triangles) {
    if (is_sliver(mesh.positions[static_cast<size_t>(t[0])], mesh.positions[static_cast<size_t>(t[1])],
                  mesh.positions[static_cast<size_t>(t[2])], diag))
      return true;
  }
  return false;
}

// After collapses: drop the vertices no face uses, renumbering in order, and carry the maps.
void remove_collapsed(CleanMesh& out, const std::vector<int>& target) {
  const size_t n = out.mesh.positions.size();
  std::vector<int> index(n, -1);
  for (const Triangle& t : out.mesh.triangles) {
    for (int v : t) index[static_cast<size_t>(v)] = 0;
  }
  std::vector<Vec3> positions;
  std::vector<int> source;
  for (size_t v = 0; v < n; ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int>(positions.size());
    positions.push_back(out.mesh.positions[v]);
    source.push_back(out.vertex_source[v]);
  }
  for (Triangle& t : out.mesh.triangles) {
    for (int& v : t) v = index[static_cast<size_t>(v)];
  }
  for (int& v : out.input_vertex_to_clean) {
    if (v < 0) continue;
    int w = v;
    while (target[static_cast<size_t>(w)] != w) w = target[static_cast<size_t>(w)];
    v = index[static_cast<size_t>(w)];
  }
  out.mesh.positions = std::move(positions);
  out.vertex_source = std::move(source);
}

}  // namespace

void repair_locally(CleanMesh& out, const CleanOptions& options) {
  CleanReport& report = out.report;
  const size_t cleaned_faces = out.mesh.triangles.size();
  std::vector<int> origin;  // current face -> face of the mesh as it came in
  bool changed = false;
  if (options.remove_slivers && has_sliver(out.mesh)) {
    std::vector<int> target;
    const SliverResult slivers = remove_slivers(out.mesh.triangles, out.mesh.positions, origin, target);
    report.slivers_removed = slivers.removed();
    if (slivers.removed() > 0) {
      changed = true;
      remove_collapsed(out, target);
    }
  }
  if (!changed) {
    origin.resize(cleaned_faces);
    for (size_t f = 0; f < cleaned_faces; ++f) origin[f] = static_cast<int>(f);
  }
  const size_t kept_faces = out.mesh.triangles.size();
  if (options.fill_holes_max_edges > 0) {
    std::vector<int> along(kept_faces);
    for (size_t f = 0; f < kept_faces; ++f) along[f] = static_cast<int>(f);
    const HoleFill fill = fill_holes(out.mesh.triangles, out.mesh.positions, options.fill_holes_max_edges, along);
    report.holes_filled = fill.holes_filled;
    report.hole_faces_added = fill.faces_added;
    for (size_t f = kept_faces; f < along.size(); ++f) origin.push_back(origin[static_cast<size_t>(along[f])]);
    if (fill.faces_added > 0) {
      changed = true;
      // A filled part may be closed now: orient again (closed parts outward).
      const HalfEdgeGroups groups = group_half_edges(out.mesh.triangles, out.mesh.num_vertices());
      const OrientResult orient = orient_faces(out.mesh.triangles, groups, out.mesh.positions, out.vertex_source,
                                               options.orient_closed_outward);
      report.faces_flipped += orient.faces_flipped;
      report.components = orient.components;
    }
  }
  if (!changed) return;
  std::vector<int> source(out.mesh.triangles.size());
  for (size_t f = 0; f < source.size(); ++f) source[f] = out.face_source[static_cast<size_t>(origin[f])];
  out.face_source = std::move(source);
  out.input_face_to_clean.assign(out.input_face_to_clean.size(), -1);
  for (size_t f = 0; f < kept_faces; ++f) out.input_face_to_clean[static_cast<size_t>(out.face_source[f])] = static_cast<int>(f);
}

}  // namespace ff::detail
