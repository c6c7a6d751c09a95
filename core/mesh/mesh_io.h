#pragma once
// Mesh readers (OBJ, OFF, STL ASCII/binary, PLY ASCII/binary little-endian) and the OBJ
// writer. Readers return the raw triangles in file order (polygons triangulated, see
// RawMesh::source_polygon) without cleaning: clean_mesh() (clean.h) welds, drops and
// orients. Every reader throws InputError with one line naming the format, the problem
// and, where it has one, the line or byte offset: empty, truncated, binary garbage in a
// text format, NaN/Inf coordinates, out-of-range or malformed indices.
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

enum class MeshFormat { Obj, Off, Stl, Ply };

struct RawMesh {
  TriMesh mesh;
  // For each triangle, the index of the polygon (face record) of the file it came from;
  // equal to the triangle index when the file holds triangles only.
  std::vector<int> source_polygon;
  int num_polygons = 0;
};

// Picks the format from the file name's extension (case-insensitive); for an unknown
// extension, from the content (magic words "OFF", "ply", "solid", binary STL size rule).
// Throws InputError when neither tells.
MeshFormat detect_format(std::string_view name, std::string_view data);

RawMesh read_obj(std::string_view data);
RawMesh read_off(std::string_view data);
RawMesh read_stl(std::string_view data);
RawMesh read_ply(std::string_view data);

// Reads from memory (the wasm path) or from a file; name is used for format detection and
// in messages.
RawMesh read_mesh(std::string_view data, std::string_view name);
RawMesh read_mesh_file(const std::string& path);

// Writes `v` lines at full precision (%.17g) and one 1-based `f` line per triangle.
void write_obj(std::ostream& out, const TriMesh& mesh);

// A polygon mesh as OBJ text (the panels file, DESIGN.md 4): optional `# ` comment lines (one
// per line of `comment`), shared `v` lines at %.17g, one 1-based `f` line per polygon without
// texture or normal indices. Face indices must lie in [0, vertices.size()).
std::string write_polygon_obj(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces,
                              const std::string& comment = {});

}  // namespace ff
