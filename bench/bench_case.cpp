#include "bench/bench_case.h"

#include <cstdio>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/shapes/shapes.h"

namespace ff::bench {

bool parse_case(const std::string& name, Case& c) {
  c = Case{};
  c.name = name;
  if (name == "roof-10k") {
    c.label = "roof ~10k";
    c.target_faces = 10000;
    c.panels = 100;
  } else if (name == "roof-100k") {
    c.label = "roof ~100k";
    c.target_faces = 100000;
    c.panels = 1000;
  } else if (name == "roof-1m") {
    c.label = "roof ~1M";
    c.target_faces = 1000000;
    c.panels = 1000;
  } else if (name == "hyperboloid") {
    c.label = "hyperboloid_s4.off";
    c.file = "hyperboloid_s4.off";
    c.panels = 500;
  } else if (name.rfind("roof:", 0) == 0) {
    int faces = 0, panels = 0;
    if (std::sscanf(name.c_str(), "roof:%d:%d", &faces, &panels) != 2 || faces < 2 || panels < 1) return false;
    c.label = "roof ~" + std::to_string(faces);
    c.target_faces = faces;
    c.panels = panels;
  } else {
    return false;
  }
  return true;
}

TriMesh make_input(const Case& c, const std::string& meshes) {
  if (c.file.empty()) {
    const int r = grid_resolution_for(c.target_faces);
    return make_roof(r, r);
  }
  const RawMesh raw = read_mesh_file(meshes + "/" + c.file);
  return clean_mesh(raw.mesh).mesh;
}

}  // namespace ff::bench
