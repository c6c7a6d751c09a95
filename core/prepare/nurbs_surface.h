#pragma once
// NURBS surfaces as Rhino (openNURBS, rhino3dm) stores them: degrees, knot vectors, a grid of
// control points with weights. Validation turns anything the evaluator cannot take into an
// InputError naming the surface and the problem; evaluation is de Boor / Cox with the
// rational quotient rule for the first derivatives (The NURBS Book, A2.2, A2.3, eq. 4.20).
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct NurbsSurface {
  int degree_u = 1;
  int degree_v = 1;
  int count_u = 0;  // control points along u
  int count_v = 0;  // control points along v
  // Either convention: openNURBS's count + degree - 1 knots (what rhino3dm gives), or the
  // textbook count + degree + 1 (one more knot at each end). validate_nurbs() makes them
  // textbook.
  std::vector<double> knots_u;
  std::vector<double> knots_v;
  // count_u * count_v points, point (i, j) at index i * count_v + j (i along u), as Euclidean
  // coordinates (not premultiplied by the weight).
  std::vector<Vec3> points;
  // One per point, or empty for a non-rational surface (all 1).
  std::vector<double> weights;
};

// Limits of what the page and the CLI accept (a hostile file must not exhaust memory).
inline constexpr int kMaxNurbsDegree = 11;              // openNURBS's practical maximum
inline constexpr int kMaxNurbsControlPoints = 1 << 20;  // per surface

// Checks `s` and returns it with textbook knot vectors and explicit weights. Throws
// InputError "<name>: ..." for degrees below 1 or above kMaxNurbsDegree, fewer control points
// than degree + 1, more than kMaxNurbsControlPoints, a knot count fitting neither convention,
// non-finite or decreasing knots, an empty domain, an interior knot repeated more than the
// degree, non-finite points, and weights that are not positive and finite.
NurbsSurface validate_nurbs(const NurbsSurface& s, const std::string& name);

// The parameter domain [u0, u1] x [v0, v1] of a validated surface.
struct NurbsDomain {
  double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
};
NurbsDomain nurbs_domain(const NurbsSurface& s);

// The distinct knot values inside the domain, ends included (knot span boundaries) along u
// (`along_u`) or v: tessellation samples each span separately so it never straddles a kink.
std::vector<double> nurbs_breaks(const NurbsSurface& s, bool along_u);

struct NurbsPoint {
  Vec3 p = Vec3::Zero();
  Vec3 du = Vec3::Zero();  // dS/du
  Vec3 dv = Vec3::Zero();  // dS/dv
};

// Point and first partial derivatives at (u, v), clamped into the domain. `s` must be
// validated (textbook knots, weights present).
NurbsPoint evaluate_nurbs(const NurbsSurface& s, double u, double v);

}  // namespace ff
