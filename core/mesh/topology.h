#pragma once
// MeshTopology: edges, face adjacency, vertex->face incidence, boundary loops, connected
// components and Euler characteristic of a TriMesh that is an edge-manifold (every edge in
// at most two faces). build_topology() throws InputError naming the first non-manifold edge
// otherwise; clean_mesh() (clean.h) is the place that repairs or refuses such input.
#include <array>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct MeshTopology {
  // Undirected edges, each stored once with vertices[e][0] < vertices[e][1].
  std::vector<std::array<int, 2>> edge_vertices;
  // The one or two faces of an edge; edge_faces[e][1] == -1 on the boundary.
  std::vector<std::array<int, 2>> edge_faces;
  // face_edges[f][i] is the edge from triangles[f][i] to triangles[f][(i+1)%3].
  std::vector<std::array<int, 3>> face_edges;
  // face_neighbors[f][i] is the face across face_edges[f][i], or -1 on the boundary.
  std::vector<std::array<int, 3>> face_neighbors;
  // Faces around each vertex in CSR form: vertex_faces[vertex_face_offsets[v] ..
  // vertex_face_offsets[v+1]), in increasing face order.
  std::vector<int> vertex_face_offsets;
  std::vector<int> vertex_faces;
  // Boundary loops as closed vertex cycles (first vertex not repeated), each oriented
  // like the faces next to it; loops ordered by their smallest vertex index.
  std::vector<std::vector<int>> boundary_loops;
  // Connected components over face adjacency (edge-connected), numbered from 0 in order
  // of their lowest face index.
  std::vector<int> face_component;
  int num_components = 0;

  int num_edges() const { return static_cast<int>(edge_vertices.size()); }
  bool is_boundary_edge(int e) const { return edge_faces[static_cast<size_t>(e)][1] < 0; }
};

// Builds all of the above in O(m log m). Vertices referenced by no face are ignored by
// the Euler characteristic. Throws InputError on an edge shared by three or more faces.
MeshTopology build_topology(const TriMesh& mesh);

// V - E + F over referenced vertices.
int euler_characteristic(const TriMesh& mesh, const MeshTopology& topology);

// Which corner of t (0, 1 or 2) is vertex v; 2 when v is none of the first two.
inline int local_index(const Triangle& t, int v) { return t[0] == v ? 0 : (t[1] == v ? 1 : 2); }

// Per connected component (face_component's numbering): 1 when it has no boundary edge.
std::vector<char> closed_components(const MeshTopology& topology);

// Per component: its shape as a surface. V - E + F = 2 - 2 handles - boundary loops.
struct PartShape {
  bool closed = true;
  int euler = 0;  // V - E + F of the component alone
  int boundary_loops = 0;
  int handles() const { return (2 - boundary_loops - euler) / 2; }  // the genus
};
std::vector<PartShape> part_shapes(const MeshTopology& topology);

// The fewest planar panels a part of this shape can become, by counting: panels are discs
// (F of them), each meets each neighbour along one side (a chain on the line where their
// planes meet), so at most F(F-1)/2 shared sides E; a node joins three panels or more (3V <=
// 2E) and two nodes one side at most (E <= V(V-1)/2); a closed part's panels have three sides
// or more (3F <= 2E); and V - E + F is the part's Euler characteristic, which on an open part
// counts only inner nodes and shared sides. Sphere 4 (a tetrahedron), torus 5, three handles
// closed 7; a disc 1, an annulus 3 (a band of three), three handles and four boundary loops 6.
// A necessary count, not always enough (no torus of planar faces has fewer than 7 known).
int fewest_panels(const PartShape& shape);
// Per component (face_component's numbering).
std::vector<int> fewest_panels(const MeshTopology& topology);

// Per component: the fewest of n clusters it should keep, so that every part can become valid
// panels: fewest_panels() when n covers their sum, else one each (a clustering of fewer).
std::vector<int> cluster_floors(const MeshTopology& topology, int n);

// True when an edge at v has one face only.
bool is_boundary_vertex(const TriMesh& mesh, const MeshTopology& topology, int v);

}  // namespace ff
