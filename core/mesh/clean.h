#pragma once
// Clean-up between reading and remeshing: weld coincident vertices, drop degenerate and
// duplicate faces, split non-manifold vertices, make the orientation consistent (closed
// parts outward), drop unreferenced vertices, and refuse what we cannot handle
// (non-manifold edges, non-orientable surfaces, non-finite coordinates, bad indices, no
// faces left) with an InputError naming where. Everything done is counted in CleanReport.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct CleanOptions {
  // Vertices closer than this (absolute) are welded; 0 welds exactly coincident ones only.
  // Only vertices on open edges (or unused) are welded: two sheets that merely touch at a
  // vertex whose edges are all shared already (cow.off has one) stay apart, instead of
  // becoming a non-manifold edge.
  double weld_tolerance = 0.0;
  // Orient closed components so their signed volume is positive (normals outward).
  bool orient_closed_outward = true;
};

struct CleanReport {
  int input_vertices = 0;
  int input_faces = 0;
  int welded_vertices = 0;           // vertices merged into another one
  int degenerate_faces_dropped = 0;  // faces with a repeated vertex after welding
  int duplicate_faces_dropped = 0;   // faces with the same vertex set as an earlier face
  int zero_area_faces = 0;           // kept (they carry no weight), counted for the report
  int nonmanifold_vertices_split = 0;
  int faces_flipped = 0;  // to make orientation consistent
  int unreferenced_vertices_removed = 0;
  int components = 0;

  // One human sentence per repair that happened, e.g. "welded 12 duplicate vertices".
  std::vector<std::string> messages() const;
};

struct CleanMesh {
  TriMesh mesh;
  // Cleaned face -> input face, and input face -> cleaned face (-1 when dropped).
  std::vector<int> face_source;
  std::vector<int> input_face_to_clean;
  // Input vertex -> cleaned vertex (-1 when removed); cleaned vertices may have several
  // input vertices (welding) and an input vertex split at a non-manifold vertex maps to
  // the first of its copies.
  std::vector<int> input_vertex_to_clean;
  // Cleaned vertex -> the input vertex it stands for (a split copy -> its original).
  std::vector<int> vertex_source;
  CleanReport report;
};

CleanMesh clean_mesh(const TriMesh& input, const CleanOptions& options = {});

}  // namespace ff
