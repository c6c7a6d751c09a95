#pragma once
// PolyMesh: a polygon mesh (faces as vertex loops) for the algorithms that need the file's
// real polygons, such as Catmull-Clark subdivision (prepare/subdivision.h). The readers
// (mesh_io.h) hand out triangles plus the file polygon each came from; merge_polygons()
// turns the (cleaned) triangles back into those polygons.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct PolyMesh {
  std::vector<Vec3> positions;
  // Face loops one after the other: face f is corners[face_start[f] .. face_start[f + 1]),
  // counter-clockwise seen from the side the normal points to.
  std::vector<int> corners;
  std::vector<int> face_start{0};

  int num_vertices() const { return static_cast<int>(positions.size()); }
  int num_faces() const { return static_cast<int>(face_start.size()) - 1; }
  int face_size(int f) const {
    return face_start[static_cast<size_t>(f) + 1] - face_start[static_cast<size_t>(f)];
  }
  // The i-th vertex of face f (0 <= i < face_size(f)).
  int corner(int f, int i) const {
    return corners[static_cast<size_t>(face_start[static_cast<size_t>(f)] + i)];
  }
  void add_face(const std::vector<int>& loop);
  // True when every face is a triangle (and there is at least one face).
  bool all_triangles() const;
};

// One face per triangle.
PolyMesh poly_mesh_from_triangles(const TriMesh& mesh);

// Merges the triangles of each polygon back into one face: face_polygon[f] names the polygon
// triangle f belongs to (for a reader's output after clean_mesh():
// raw.source_polygon[clean.face_source[f]]). A polygon's triangles are merged when they form
// one disk without inner vertices (k - 2 triangles whose outer edges make one loop of k
// distinct vertices); otherwise they stay triangles. Faces are ordered by polygon number,
// then by first triangle; a merged loop starts at its first triangle's first outer edge.
// Indices are not checked here: face_polygon must have one entry per triangle.
PolyMesh merge_polygons(const TriMesh& mesh, const std::vector<int>& face_polygon);

// face_polygon for merge_polygons() after clean_mesh(): the file polygon of each cleaned
// triangle, from CleanMesh::face_source and RawMesh::source_polygon (a triangle the reader
// did not map, or every one when source_polygon is empty, is its own polygon).
std::vector<int> cleaned_face_polygons(const std::vector<int>& face_source, const std::vector<int>& source_polygon);

// Triangles of every face, keeping its orientation: quads split along the shorter diagonal
// (the 0-2 one on a tie), larger faces as a fan from their first vertex.
TriMesh triangulate(const PolyMesh& mesh);

// The Newell normal of face f (unit length; zero for a degenerate face).
Vec3 polygon_normal(const PolyMesh& mesh, int f);

}  // namespace ff
