#pragma once
// bench_remesh's inputs: the named cases (shared meshes and generated shapes) with the panel
// count each is remeshed into, and the read (or make) + clean both sides start from.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::bench {

struct RemeshCase {
  std::string name;   // command-line id
  std::string label;  // table label
  std::string file;   // a file in the meshes folder, or
  std::string shape;  // "saddle" / "torus" (core/shapes/hard_cases.h) of about `triangles`
  int triangles = 0;
  int panels = 0;
};

// The full run's cases, and the smoke run's.
extern const std::vector<std::string> kRemeshFullRun;
extern const char* const kRemeshSmokeCase;

// Named cases, or "saddle:TRIANGLES:PANELS", "torus:TRIANGLES:PANELS", "mesh:FILE:PANELS".
bool parse_remesh_case(const std::string& name, RemeshCase& c);

// Read (or make) and clean: the part of the whole process both sides share.
TriMesh load_remesh_case(const RemeshCase& c, const std::string& meshes);

}  // namespace ff::bench
