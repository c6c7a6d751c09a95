#include "core/prepare/nurbs_json.h"

#include <cmath>
#include <initializer_list>
#include <utility>

#include "core/util/error.h"
#include "core/util/json_reader.h"

namespace ff {

namespace {

using Type = JsonValue::Type;

double number(const JsonValue& v, const std::string& what) {
  if (v.type != Type::Number || !std::isfinite(v.number)) throw InputError(what + " must be a number");
  return v.number;
}

int integer(const JsonValue& v, const std::string& what, int lo, int hi) {
  const double x = number(v, what);
  if (x != std::floor(x) || x < lo || x > hi)
    throw InputError(what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(x);
}

std::vector<double> numbers(const JsonValue& v, const std::string& what) {
  if (v.type != Type::Array) throw InputError(what + " must be an array of numbers");
  std::vector<double> out;
  out.reserve(v.array.size());
  for (size_t k = 0; k < v.array.size(); ++k) out.push_back(number(v.array[k], what + "[" + std::to_string(k) + "]"));
  return out;
}

NamedSurface surface(const JsonValue& v, size_t index) {
  const std::string where = "surface " + std::to_string(index);
  if (v.type != Type::Object) throw InputError(where + " must be a JSON object");
  NamedSurface out;
  out.name = where;
  if (const JsonValue* name = v.find("name")) {
    if (name->type != Type::String || name->string.size() > 200)
      throw InputError(where + " 'name' must be a string of at most 200 bytes");
    if (!name->string.empty()) out.name = name->string;  // as given: the page quotes object names
  }
  const std::string& n = out.name;
  const JsonValue *du = nullptr, *dv = nullptr, *cu = nullptr, *cv = nullptr, *ku = nullptr, *kv = nullptr,
                  *pts = nullptr, *w = nullptr;
  for (const auto& [key, value] : v.object) {
    if (key == "name") continue;
    const JsonValue** slot = key == "degreeU"   ? &du
                             : key == "degreeV" ? &dv
                             : key == "countU"  ? &cu
                             : key == "countV"  ? &cv
                             : key == "knotsU"  ? &ku
                             : key == "knotsV"  ? &kv
                             : key == "points"  ? &pts
                             : key == "weights" ? &w
                                                : nullptr;
    if (!slot) throw InputError(n + ": unknown key '" + key + "'");
    *slot = &value;
  }
  for (const auto& [ptr, key] : std::initializer_list<std::pair<const JsonValue*, const char*>>{{du, "degreeU"},
                                                                                                {dv, "degreeV"},
                                                                                                {cu, "countU"},
                                                                                                {cv, "countV"},
                                                                                                {ku, "knotsU"},
                                                                                                {kv, "knotsV"},
                                                                                                {pts, "points"}})
    if (!ptr) throw InputError(n + ": '" + key + "' is missing");
  NurbsSurface s;
  s.degree_u = integer(*du, n + " 'degreeU'", 1, kMaxNurbsDegree);
  s.degree_v = integer(*dv, n + " 'degreeV'", 1, kMaxNurbsDegree);
  s.count_u = integer(*cu, n + " 'countU'", 2, kMaxNurbsControlPoints);
  s.count_v = integer(*cv, n + " 'countV'", 2, kMaxNurbsControlPoints);
  s.knots_u = numbers(*ku, n + " 'knotsU'");
  s.knots_v = numbers(*kv, n + " 'knotsV'");
  const std::vector<double> xyz = numbers(*pts, n + " 'points'");
  if (xyz.size() % 3 != 0) throw InputError(n + ": 'points' must hold x, y, z triples");
  for (size_t k = 0; k < xyz.size(); k += 3) s.points.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
  if (w) s.weights = numbers(*w, n + " 'weights'");
  out.surface = validate_nurbs(s, n);
  return out;
}

}  // namespace

SurfaceSet surface_set_from_json(std::string_view json) {
  const JsonValue root = parse_json(json, 5, kMaxSurfaceJsonBytes);
  if (root.type != Type::Object) throw InputError("the surface description must be a JSON object");
  SurfaceSet set;
  const JsonValue* surfaces = nullptr;
  for (const auto& [key, value] : root.object) {
    if (key == "surfaces") {
      surfaces = &value;
    } else if (key == "targetTriangles") {
      set.target_triangles = integer(value, "'targetTriangles'", 100, 2000000);
    } else if (key == "edgeLength") {
      set.edge_length = number(value, "'edgeLength'");
      if (!(set.edge_length > 0.0)) throw InputError("'edgeLength' must be above 0");
    } else if (key == "weldTolerance") {
      set.weld_tolerance = number(value, "'weldTolerance'");
      if (set.weld_tolerance < 0.0) throw InputError("'weldTolerance' must be at least 0");
    } else {
      throw InputError("unknown key '" + key + "' in the surface description");
    }
  }
  if (!surfaces || surfaces->type != Type::Array) throw InputError("the surface description needs a 'surfaces' array");
  if (surfaces->array.size() > static_cast<size_t>(kMaxSurfaces))
    throw InputError("more than " + std::to_string(kMaxSurfaces) + " surfaces");
  for (size_t k = 0; k < surfaces->array.size(); ++k) set.surfaces.push_back(surface(surfaces->array[k], k));
  return set;
}

}  // namespace ff
