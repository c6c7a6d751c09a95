#pragma once
// Per-vertex normals and principal curvatures (for procedural density and anisotropy,
// paper 3.3). Curvature comes from a least-squares quadric fit over each vertex's 2-ring in
// its tangent frame, h(a, b) = A a^2 + B ab + C b^2 + D a + E b: the linear terms absorb a
// slightly-off vertex normal, and the shape operator of that graph (first and second
// fundamental forms at the vertex) gives the curvatures and directions. Robust on irregular
// triangulations and at boundaries (the 2-ring there is one-sided, which a fit tolerates),
// O(ring size) per vertex.
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

// Area-weighted unit vertex normals (zero for vertices without faces of non-zero area).
std::vector<Vec3> vertex_normals(const TriMesh& mesh, const MeshTopology& topology);

struct VertexCurvature {
  // Principal curvatures, k1 >= k2, positive where the surface bends away from its normal
  // (the outside of a sphere of radius R: k1 = k2 = 1/R). World units (1 / length).
  std::vector<double> k1, k2;
  // Unit principal directions (tangent), dir1 for k1; the sign of a direction is arbitrary.
  std::vector<Vec3> dir1, dir2;
  std::vector<Vec3> normal;  // unit vertex normals (vertex_normals)
};

// All vertices; isolated or degenerate ones (fewer than three distinct neighbours) get zero
// curvature and an arbitrary tangent frame.
VertexCurvature vertex_curvature(const TriMesh& mesh, const MeshTopology& topology);

}  // namespace ff
