// Session::set_repair: the page's repair options (issue 7), the same as `flatfacet remesh
// --fill-holes N --largest-part` (cli/input.cpp), and what the load repaired, as numbers.
#include <string>

#include "core/util/error.h"
#include "wasm/guarded.h"
#include "wasm/session.h"

namespace ff::wasm {

std::string Session::set_repair(int fill_holes, bool largest_part) {
  return guarded([&] {
    if (fill_holes < 0 || fill_holes > 500)
      throw InputError("holes to fill must have 0 (off) to 500 edges, not " + std::to_string(fill_holes));
    repair_.fill_holes_max_edges = fill_holes;
    repair_.largest_manifold_part = largest_part;
    return status_json(true, "");
  });
}

void Session::write_repair_json(JsonWriter& j) const {
  const CleanReport& c = clean_report_;
  j.begin_object("repair");
  j.value("fillHoles", repair_.fill_holes_max_edges).value("largestPart", repair_.largest_manifold_part);
  j.value("slivers", c.slivers_removed).value("holesFilled", c.holes_filled).value("holeFaces", c.hole_faces_added);
  j.value("nonmanifoldEdgesCut", c.nonmanifold_edges_cut).value("facesDropped", c.faces_outside_part);
  j.value("partsDropped", c.parts_dropped);
  j.end_object();
}

}  // namespace ff::wasm
