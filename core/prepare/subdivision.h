#pragma once
// Subdivision surfaces: refine a coarse control mesh towards its smooth limit surface, so a
// designer's low-poly model can be remeshed into far more panels than it has faces.
//  - Loop (triangle meshes): each triangle -> 4 per level.
//  - Catmull-Clark (any polygons): an n-gon -> n quads at the first level, each quad -> 4
//    after; the final quads are split into two triangles along their shorter diagonal.
// Sharp features: boundary edges and the given crease edges follow the cubic B-spline curve
// rules (edge point = midpoint, vertex = (a + 6v + b) / 8 from its two crease neighbours); a
// vertex with three or more crease edges is a corner and stays where it is, and so does a
// boundary vertex of a single face (a valence-2 boundary corner). Children of a crease edge
// are crease edges, so a crease stays sharp at every level. Vertex numbering: level k's
// vertices keep their numbers at level k+1, then one vertex per edge (in (min, max) vertex
// order), then (Catmull-Clark) one per face; face orientation is kept.
//
// Input must be an oriented edge-manifold (what clean_mesh() returns): an edge in three or
// more faces, or two faces disagreeing on the orientation of an edge, is an InputError, and
// so is a face with fewer than 3 or repeated vertices, a bad index, or a result that would
// exceed max_triangles. Deterministic: no hash maps, edges and faces in sorted order.
#include <array>
#include <vector>

#include "core/mesh/poly_mesh.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

using VertexPair = std::array<int, 2>;

// The default cap on the triangles a subdivision may produce (each level multiplies by 4).
constexpr long long kMaxSubdivisionTriangles = 4'000'000;

enum class SubdivisionScheme { Loop, CatmullClark };
const char* scheme_name(SubdivisionScheme scheme);  // "loop" or "catmull-clark"

// Triangles `levels` levels of `scheme` turn `mesh` into (saturating at a huge value instead
// of overflowing). Catmull-Clark with 0 levels: the triangles of the control polygons.
long long subdivided_triangle_count(const PolyMesh& mesh, SubdivisionScheme scheme, int levels);

// Interior edges of `mesh` whose two faces' normals (Newell normals) differ by more than
// `angle_deg` degrees, as (smaller vertex, larger vertex) pairs in increasing order. Any
// angle of 180 or more gives none. Throws InputError on non-manifold input.
std::vector<VertexPair> crease_edges(const PolyMesh& mesh, double angle_deg);

// Loop subdivision of a triangle mesh; `creases` lists control-mesh edges kept sharp (each
// must be an edge of `mesh`, in either vertex order). levels >= 0.
TriMesh loop_subdivide(const TriMesh& mesh, int levels, const std::vector<VertexPair>& creases = {},
                       long long max_triangles = kMaxSubdivisionTriangles);

// Catmull-Clark subdivision before triangulation: with levels >= 1 every face is a quad.
PolyMesh catmull_clark_quads(const PolyMesh& mesh, int levels, const std::vector<VertexPair>& creases = {},
                             long long max_triangles = kMaxSubdivisionTriangles);

// catmull_clark_quads() triangulated (triangulate() in poly_mesh.h).
TriMesh catmull_clark(const PolyMesh& mesh, int levels, const std::vector<VertexPair>& creases = {},
                      long long max_triangles = kMaxSubdivisionTriangles);

// A file's surface as a control mesh: its polygons (merge_polygons(mesh, face_polygon))
// subdivided `levels` levels, Loop when every polygon is a triangle, else Catmull-Clark, with
// crease_edges(angle) kept sharp. What `flatfacet remesh --subdivide` and the page do.
struct ControlSubdivision {
  TriMesh mesh;  // triangulated, not yet cleaned
  SubdivisionScheme scheme = SubdivisionScheme::Loop;
  int control_vertices = 0;
  int control_faces = 0;
  int crease_edges = 0;
};
ControlSubdivision subdivide_control_mesh(const TriMesh& mesh, const std::vector<int>& face_polygon, int levels,
                                          double crease_angle_deg = 180.0);

}  // namespace ff
