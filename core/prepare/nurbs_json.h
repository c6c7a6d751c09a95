#pragma once
// The surface description the page sends (wasm Session::load_surfaces, flatfacet.d.ts
// SurfaceSet): NURBS surfaces read from a Rhino file plus how finely to tessellate them.
// Checked strictly (unknown keys, wrong types, out-of-range numbers and oversized text are
// refused with an InputError naming the key and the surface), every surface validated by
// validate_nurbs().
//
//   {"targetTriangles": 30000,          optional, 100 .. 2e6: picks the edge length
//    "edgeLength": 0.05,                optional, > 0: overrides targetTriangles
//    "weldTolerance": 0.001,            optional, >= 0: joins surfaces and meshes closer than it
//    "surfaces": [{"name": "'Vault'", "degreeU": 2, "degreeV": 1, "countU": 9, "countV": 2,
//                  "knotsU": [...], "knotsV": [...],        either knot convention
//                  "points": [x, y, z, ...],                 countU * countV, (i, j) at i * countV + j
//                  "weights": [...]}]}                       optional, one per point
#include <string>
#include <string_view>
#include <vector>

#include "core/prepare/nurbs_surface.h"

namespace ff {

struct NamedSurface {
  std::string name;      // as given (the page sends "'Vault'", "face 2 of 'Tank'"), else "surface <k>"
  NurbsSurface surface;  // validated
};

struct SurfaceSet {
  std::vector<NamedSurface> surfaces;
  int target_triangles = 30000;
  double edge_length = 0.0;  // 0: from target_triangles
  double weld_tolerance = 0.0;
};

inline constexpr size_t kMaxSurfaceJsonBytes = 16u << 20;
inline constexpr int kMaxSurfaces = 10000;

SurfaceSet surface_set_from_json(std::string_view json);

}  // namespace ff
