#include "core/shapes/example_shapes.h"

#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"

namespace ff {

std::vector<std::string> example_shape_names() {
  return {"saddle", "barrel_vault",   "groin_vault",   "helicoid", "freeform_roof", "torus",
          "bump",   "roof_with_hole", "twisted_strip", "cone",     "monkey_saddle"};
}

TriMesh make_example_shape(const std::string& name, int triangles) {
  if (triangles < 100 || triangles > 4'000'000)
    throw InputError("example '" + name + "': triangles must be between 100 and 4000000");
  if (name == "freeform_roof") {
    const int r = grid_resolution_for(triangles);
    return make_roof(r, r);
  }
  if (name == "saddle") return make_saddle(triangles);
  if (name == "barrel_vault") return make_barrel_vault(triangles);
  if (name == "groin_vault") return make_groin_vault(triangles);
  if (name == "helicoid") return make_helicoid(triangles);
  if (name == "torus") return make_torus(triangles);
  if (name == "bump") return make_bump(triangles);
  if (name == "roof_with_hole") return make_roof_with_hole(triangles);
  if (name == "twisted_strip") return make_twisted_strip(triangles);
  if (name == "cone") return make_cone(triangles);
  if (name == "monkey_saddle") return make_monkey_saddle(triangles);
  throw InputError("unknown example shape '" + name + "'");
}

}  // namespace ff
