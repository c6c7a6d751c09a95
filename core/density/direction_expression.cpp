#include "core/density/direction_expression.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

#include "core/util/error.h"

namespace ff {

namespace {

const char* const kAxis[3] = {"x", "y", "z"};

std::string number_text(double x) {
  if (std::isnan(x)) return "NaN";  // not "-nan" on some platforms
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

[[noreturn]] void fail_component(int i, const std::string& what) {
  throw InputError("direction expression, component " + std::to_string(i + 1) + " (" + kAxis[i] + ") " + what);
}

}  // namespace

bool DirectionExpression::uses_curvature() const {
  for (const Expression& e : components)
    if (e.uses_curvature()) return true;
  return false;
}

DirectionExpression parse_direction_expression(std::string_view text) {
  if (text.size() > Expression::kMaxLength) {
    throw InputError("direction expression is too long (" + std::to_string(text.size()) + " characters; at most " +
                     std::to_string(Expression::kMaxLength) + ")");
  }
  // Top-level commas only: those inside brackets separate a function's arguments.
  // Unbalanced brackets would hide the commas, so they are named first.
  std::array<size_t, 4> bounds{};  // component i is [bounds[i] + (i > 0), bounds[i + 1])
  int commas = 0;
  std::vector<size_t> open;  // columns of the brackets not yet closed
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') open.push_back(i);
    if (text[i] == ')') {
      if (open.empty()) throw InputError("direction expression has an unmatched ')' at column " + std::to_string(i + 1));
      open.pop_back();
    }
    if (text[i] != ',' || !open.empty()) continue;
    if (commas == 2)
      throw InputError("direction expression has more than three components (a third comma at column " +
                       std::to_string(i + 1) + "); write x, y, z");
    bounds[static_cast<size_t>(++commas)] = i;
  }
  if (!open.empty())
    throw InputError("direction expression has a '(' at column " + std::to_string(open.back() + 1) + " that is not closed");
  if (commas != 2) {
    throw InputError("direction expression needs three components separated by commas (x, y, z), e.g. \"-y, x, 0\"; it has " +
                     std::to_string(commas + 1));
  }
  bounds[3] = text.size();
  DirectionExpression out;
  int terms = 0;
  for (int c = 0; c < 3; ++c) {
    const size_t begin = c == 0 ? 0 : bounds[static_cast<size_t>(c)] + 1, end = bounds[static_cast<size_t>(c) + 1];
    // The other components blanked out, so the parser's columns are columns of the whole text.
    std::string padded(text.size(), ' ');
    bool blank = true;
    for (size_t i = begin; i < end; ++i) {
      padded[i] = text[i];
      blank = blank && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r');
    }
    if (blank) fail_component(c, "is empty (column " + std::to_string(begin + 1) + ")");
    try {
      out.components[static_cast<size_t>(c)] = Expression::parse(padded);
    } catch (const InputError& e) {
      // The parser speaks of a "density expression": keep what follows.
      std::string what = e.what();
      const std::string prefix = "density expression ";
      if (what.compare(0, prefix.size(), prefix) == 0) what.erase(0, prefix.size());
      fail_component(c, what);
    }
    // Directions are evaluated per face without the border distances (a density input).
    if (out.components[static_cast<size_t>(c)].uses(ExprVar::Border))
      fail_component(c, "uses border, which only density expressions have");
    terms += out.components[static_cast<size_t>(c)].num_terms();
  }
  if (terms > Expression::kMaxTerms) {
    throw InputError("direction expression has too many terms (" + std::to_string(terms) + " in its three components; at most " +
                     std::to_string(Expression::kMaxTerms) + ")");
  }
  return out;
}

std::vector<Vec3> expression_face_directions(const TriMesh& mesh, const DirectionExpression& expr,
                                             const VertexCurvature* curvature) {
  if (expr.uses_curvature() && curvature == nullptr)
    throw InputError("direction expression: curvature is needed but was not computed");
  const BoundingBox box = bounding_box(mesh);
  const Vec3 extent = box.hi - box.lo;
  const double diagonal = bbox_diagonal(mesh);
  std::vector<Vec3> out(mesh.triangles.size(), Vec3::Zero());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& p0 = mesh.positions[static_cast<size_t>(t[0])];
    const Vec3& p1 = mesh.positions[static_cast<size_t>(t[1])];
    const Vec3& p2 = mesh.positions[static_cast<size_t>(t[2])];
    const Vec3 c = (p0 + p1 + p2) / 3.0;
    const Vec3 cross = (p1 - p0).cross(p2 - p0);
    const double len = cross.norm();
    const Vec3 n = len > 0.0 && std::isfinite(len) ? Vec3(cross / len) : Vec3::Zero();
    ExprInputs in{};
    const auto set = [&in](ExprVar var, double value) { in[static_cast<size_t>(var)] = value; };
    set(ExprVar::X, c.x());
    set(ExprVar::Y, c.y());
    set(ExprVar::Z, c.z());
    // Per axis 0..1 over the box; a flat axis sits at its middle (as expression_density).
    for (int a = 0; a < 3; ++a) {
      const double u = extent[a] > 0.0 ? (c[a] - box.lo[a]) / extent[a] : 0.5;
      in[static_cast<size_t>(ExprVar::U) + static_cast<size_t>(a)] = std::isfinite(u) ? u : 0.5;
    }
    set(ExprVar::NX, n.x());
    set(ExprVar::NY, n.y());
    set(ExprVar::NZ, n.z());
    if (curvature) {
      double k1 = 0.0, k2 = 0.0, gauss = 0.0, curv = 0.0;
      for (int v : t) {
        const size_t i = static_cast<size_t>(v);
        k1 += curvature->k1[i] / 3.0;
        k2 += curvature->k2[i] / 3.0;
        gauss += curvature->k1[i] * curvature->k2[i] / 3.0;
        curv += 0.5 * (std::abs(curvature->k1[i]) + std::abs(curvature->k2[i])) * diagonal / 3.0;
      }
      set(ExprVar::K1, k1);
      set(ExprVar::K2, k2);
      set(ExprVar::H, 0.5 * (k1 + k2));
      set(ExprVar::K, gauss);
      set(ExprVar::Curv, curv);
    }
    Vec3 d;
    for (int a = 0; a < 3; ++a) {
      d[a] = expr.components[static_cast<size_t>(a)].evaluate(in);
      if (!std::isfinite(d[a])) {
        fail_component(a, "gives " + number_text(d[a]) + " at face " + std::to_string(f + 1) + " (centroid " +
                              number_text(c.x()) + ", " + number_text(c.y()) + ", " + number_text(c.z()) +
                              "); directions must be finite");
      }
    }
    // Scaled before the norm so huge components cannot overflow it.
    const double big = d.cwiseAbs().maxCoeff();
    if (big > 0.0) {
      d /= big;
      out[f] = d / d.norm();
    }
  }
  return out;
}

}  // namespace ff
