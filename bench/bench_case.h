#pragma once
// The benchmark's inputs: generated roofs of a given size, or a shared mesh, with the panel
// count each is clustered into.
#include <string>

#include "core/mesh/tri_mesh.h"

namespace ff::bench {

struct Case {
  std::string name;      // command-line id
  std::string label;     // table label
  int target_faces = 0;  // roof: about this many triangles
  std::string file;      // or a file in the meshes folder
  int panels = 0;
};

// "roof-10k", "roof-100k", "roof-1m", "hyperboloid", or "roof:FACES:PANELS" for any size.
bool parse_case(const std::string& name, Case& c);

// The case's mesh: a roof made here, or the file read from `meshes` and cleaned.
TriMesh make_input(const Case& c, const std::string& meshes);

}  // namespace ff::bench
