#pragma once
// Where the tests find the shared real-world meshes (../shared/meshes beside the clone,
// or $FF_SHARED_MESHES). A missing mesh is a test failure, never a skip.
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"

namespace ff::test {

inline std::string shared_mesh_dir() {
  if (const char* env = std::getenv("FF_SHARED_MESHES")) return env;
  return FF_SHARED_MESHES;
}

inline std::string shared_mesh(const std::string& name) { return shared_mesh_dir() + "/" + name; }

// A shared mesh read and cleaned as the CLI and the page do.
inline TriMesh load_clean(const std::string& file) { return clean_mesh(read_mesh_file(shared_mesh(file)).mesh).mesh; }

// Every mesh in ../shared/meshes/ with what we know about it from its README.
struct SharedMesh {
  std::string file;
  int faces;  // triangles after triangulating polygons
  bool closed;
  int boundary_loops;
};

// So GoogleTest names the mesh in failure messages.
inline void PrintTo(const SharedMesh& mesh, std::ostream* os) { *os << mesh.file; }

inline const std::vector<SharedMesh>& shared_meshes() {
  static const std::vector<SharedMesh> meshes = {
      {"inspired_mesh.obj", 4288, false, 1},
      {"hyperboloid_s4.off", 50454, false, 2},
      {"YasIsland.off", 1952, false, 3},
      {"epcot.off", 1536, true, 0},
      {"Moomoo.off", 7776, true, 0},
      {"bunny.off", 6966, true, 0},
      {"bumpy.off", 2496, true, 0},
      {"fandisk.off", 14454, true, 0},
      {"3holes.off", 7200, true, 0},
      {"camelhead.off", 22704, false, 1},
      {"cow.off", 5520, true, 0},
      {"face.obj", 51712, false, 1},
      {"lilium.obj", 6590, false, 1},
  };
  return meshes;
}

}  // namespace ff::test
