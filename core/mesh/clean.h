#pragma once
// Clean-up between reading and remeshing: weld coincident vertices, drop degenerate and
// duplicate faces, split non-manifold vertices, make the orientation consistent (closed
// parts outward), drop unreferenced vertices, remove sliver faces, fill small holes when
// asked, and refuse what we cannot handle (non-manifold edges unless asked for the largest
// manifold part, non-orientable surfaces, non-finite coordinates, bad indices, a part far
// from the rest (part_spread.h), a vertex far from all the others (vertex_spread.h), no
// faces left) with an InputError naming where. Everything done is counted in CleanReport.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/util/error.h"

namespace ff {

struct CleanOptions {
  // Vertices closer than this (absolute) are welded; 0 welds exactly coincident ones only.
  // Only vertices on open edges (or unused) are welded: two sheets that merely touch at a
  // vertex whose edges are all shared already (cow.off has one) stay apart, instead of
  // becoming a non-manifold edge.
  double weld_tolerance = 0.0;
  // Orient closed components so their signed volume is positive (normals outward).
  bool orient_closed_outward = true;
  // Remove sliver faces (area below 1e-12 diag^2, or a corner within 1e-9 diag of the
  // opposite edge's line; diag: the bounding-box diagonal) by collapsing their shortest
  // edge or flipping their longest, never changing the topology (core/mesh/slivers.h).
  // A mesh without slivers is returned exactly as without this.
  bool remove_slivers = true;
  // Fill boundary loops (holes) of at most this many edges with a least-area triangulation
  // (core/mesh/fill_holes.h); 0 = off, at most 500.
  int fill_holes_max_edges = 0;
  // Keep only the part of largest area: cut the mesh at non-manifold edges (each fan of faces
  // becomes its own sheet) instead of refusing them (NonManifoldError), and drop every other
  // part, joined to it by no edge (a stray piece, which part_spread.h refuses when far off).
  // Parts that touch only at a vertex count as separate. A mesh of one part stays as it is.
  bool largest_manifold_part = false;
};

struct CleanReport {
  int input_vertices = 0;
  int input_faces = 0;
  int welded_vertices = 0;           // vertices merged into another one
  int degenerate_faces_dropped = 0;  // faces with a repeated vertex after welding
  int duplicate_faces_dropped = 0;   // faces with the same vertex set as an earlier face
  int zero_area_faces = 0;           // left (sliver removal could not or was not to remove them)
  int slivers_removed = 0;           // sliver faces collapsed, flipped or dropped
  int holes_filled = 0;              // boundary loops filled (fill_holes_max_edges)
  int hole_faces_added = 0;          // faces those fillings added
  // largest_manifold_part: the non-manifold edges cut (0 when only separate parts were
  // dropped), the faces then (after dropping degenerate and duplicate ones), and the faces
  // and parts left out.
  int nonmanifold_edges_cut = 0;
  int faces_before_cut = 0;
  int faces_outside_part = 0;
  int parts_dropped = 0;
  int most_faces_dropped_part = 0;  // the faces of the dropped part with the most of them
  int nonmanifold_vertices_split = 0;
  int faces_flipped = 0;  // to make orientation consistent
  int unreferenced_vertices_removed = 0;
  int components = 0;

  // One human sentence per repair that happened, e.g. "welded 12 duplicate vertices".
  std::vector<std::string> messages() const;
  // Largest means largest by area, so a stray triangle far off (or one corrupted coordinate)
  // outweighs the model itself: then the part kept has fewer faces than one dropped, and
  // this says so (empty otherwise; also the end of messages()' sentence on the part).
  std::string kept_part_doubt() const;
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
  // Per input face, 1 when largest_manifold_part left it out with its part (rather than as a
  // degenerate or duplicate face); empty when no part was dropped.
  std::vector<char> input_face_outside_part;
  CleanReport report;
};

// What clean_mesh() throws for non-manifold edges without largest_manifold_part: the
// message names the first edge (vertices, position, faces) and how many more there are;
// the numbers let a caller offer the largest manifold part ("N of M faces"). A part far from
// the rest is refused with a LargestPartError too (part_spread.h).
class NonManifoldError : public LargestPartError {
 public:
  NonManifoldError(const std::string& message, int edges, int part_faces, int faces)
      : LargestPartError(message, part_faces, faces), nonmanifold_edges(edges) {}
  int nonmanifold_edges;
};

// Faces added to fill a hole stand, in face_source, for the face along the hole's first
// edge (so per-face data has a value for them); input_face_to_clean names only the face
// that came from each input face.
CleanMesh clean_mesh(const TriMesh& input, const CleanOptions& options = {});

}  // namespace ff
