#include "bench/remesh_case.h"

#include <cstdlib>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/shapes/hard_cases.h"

namespace ff::bench {

const std::vector<std::string> kRemeshFullRun = {"hyperboloid", "inspired", "bunny", "fandisk",
                                                 "face",        "saddle",   "torus"};
const char* const kRemeshSmokeCase = "saddle:3000:40";

bool parse_remesh_case(const std::string& name, RemeshCase& c) {
  struct Named {
    const char *name, *file, *shape;
    int triangles, panels;
  };
  static const Named named[] = {
      {"hyperboloid", "hyperboloid_s4.off", "", 0, 500},
      {"inspired", "inspired_mesh.obj", "", 0, 100},
      {"bunny", "bunny.off", "", 0, 200},
      {"fandisk", "fandisk.off", "", 0, 300},
      {"face", "face.obj", "", 0, 500},
      {"saddle", "", "saddle", 20000, 200},
      {"torus", "", "torus", 20000, 200},
  };
  c = RemeshCase{};
  c.name = name;
  for (const Named& n : named) {
    if (name != n.name) continue;
    c.file = n.file;
    c.shape = n.shape;
    c.triangles = n.triangles;
    c.panels = n.panels;
  }
  if (c.file.empty() && c.shape.empty()) {
    const size_t a = name.find(':'), b = name.rfind(':');
    if (a == std::string::npos || a == b) return false;
    const std::string kind = name.substr(0, a), middle = name.substr(a + 1, b - a - 1);
    c.panels = std::atoi(name.c_str() + b + 1);
    if (kind == "mesh") {
      c.file = middle;
    } else if (kind == "saddle" || kind == "torus") {
      c.shape = kind;
      c.triangles = std::atoi(middle.c_str());
      if (c.triangles < 2) return false;
    } else {
      return false;
    }
    if (c.panels < 1 || middle.empty()) return false;
  }
  c.label = !c.file.empty() ? c.file : c.shape + " ~" + std::to_string(c.triangles / 1000) + "k";
  return true;
}

// Read (or make) and clean: the part of the whole process both sides share.
TriMesh load_remesh_case(const RemeshCase& c, const std::string& meshes) {
  if (c.shape == "saddle") return ff::clean_mesh(ff::make_saddle(c.triangles)).mesh;
  if (c.shape == "torus") return ff::clean_mesh(ff::make_torus(c.triangles)).mesh;
  return ff::clean_mesh(ff::read_mesh_file(meshes + "/" + c.file).mesh).mesh;
}

}  // namespace ff::bench
