#include "core/prepare/nurbs_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "core/util/error.h"

namespace ff {

namespace {

// Textbook knots (count + degree + 1) from either convention; throws naming `what`.
std::vector<double> textbook_knots(const std::vector<double>& knots, int count, int degree, const std::string& what) {
  const size_t rhino = static_cast<size_t>(count + degree - 1);
  const size_t textbook = static_cast<size_t>(count + degree + 1);
  for (size_t k = 0; k < knots.size(); ++k)
    if (!std::isfinite(knots[k])) throw InputError(what + " knot " + std::to_string(k) + " is not finite");
  for (size_t k = 1; k < knots.size(); ++k)
    if (knots[k] < knots[k - 1]) throw InputError(what + " knots decrease at knot " + std::to_string(k));
  std::vector<double> out;
  if (knots.size() == textbook) {
    out = knots;
  } else if (knots.size() == rhino) {
    // openNURBS leaves out the first and last knot, which never affect the surface: repeat
    // the ends (any value <= / >= its neighbour would do).
    out.reserve(textbook);
    out.push_back(knots.front());
    out.insert(out.end(), knots.begin(), knots.end());
    out.push_back(knots.back());
  } else {
    throw InputError(what + " has " + std::to_string(knots.size()) + " knots; " + std::to_string(count) +
                     " control points of degree " + std::to_string(degree) + " need " + std::to_string(rhino) +
                     " (Rhino) or " + std::to_string(textbook) + " (textbook)");
  }
  const double lo = out[static_cast<size_t>(degree)];
  const double hi = out[static_cast<size_t>(count)];
  if (!(lo < hi)) throw InputError(what + " has an empty parameter domain (its knots are all equal there)");
  // An interior knot of multiplicity above the degree breaks the surface apart.
  for (size_t k = 0; k < out.size();) {
    size_t e = k;
    while (e < out.size() && out[e] == out[k]) ++e;
    if (out[k] > lo && out[k]<hi&& static_cast<int>(e - k)> degree)
      throw InputError(what + " knot " + std::to_string(out[k]) + " is repeated " + std::to_string(e - k) +
                       " times, more than the degree (the surface would be torn there)");
    k = e;
  }
  return out;
}

int find_span(const std::vector<double>& U, int count, int degree, double u) {
  if (u >= U[static_cast<size_t>(count)]) {
    // The right end belongs to the last non-empty span.
    int i = count - 1;
    while (i > degree && U[static_cast<size_t>(i)] >= U[static_cast<size_t>(count)]) --i;
    return i;
  }
  int lo = degree, hi = count;  // U[lo] <= u < U[hi]
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (u < U[static_cast<size_t>(mid)])
      hi = mid;
    else
      lo = mid;
  }
  return lo;
}

// Basis functions N[span - p + r] (r = 0..p) and their first derivatives at u (A2.3, n = 1).
void basis_and_derivative(const std::vector<double>& U, int span, int p, double u, double* N, double* dN) {
  std::array<double, kMaxNurbsDegree + 1> left{}, right{};
  std::array<std::array<double, kMaxNurbsDegree + 1>, kMaxNurbsDegree + 1> ndu{};
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[static_cast<size_t>(j)] = u - U[static_cast<size_t>(span + 1 - j)];
    right[static_cast<size_t>(j)] = U[static_cast<size_t>(span + j)] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      // Lower triangle: knot differences; upper: basis functions.
      ndu[static_cast<size_t>(j)][static_cast<size_t>(r)] =
          right[static_cast<size_t>(r + 1)] + left[static_cast<size_t>(j - r)];
      const double temp =
          ndu[static_cast<size_t>(r)][static_cast<size_t>(j - 1)] / ndu[static_cast<size_t>(j)][static_cast<size_t>(r)];
      ndu[static_cast<size_t>(r)][static_cast<size_t>(j)] = saved + right[static_cast<size_t>(r + 1)] * temp;
      saved = left[static_cast<size_t>(j - r)] * temp;
    }
    ndu[static_cast<size_t>(j)][static_cast<size_t>(j)] = saved;
  }
  for (int r = 0; r <= p; ++r) N[r] = ndu[static_cast<size_t>(r)][static_cast<size_t>(p)];
  // First derivative: p * (N_{r,p-1} / (u_{r+p} - u_r) - N_{r+1,p-1} / (u_{r+p+1} - u_{r+1})).
  for (int r = 0; r <= p; ++r) {
    double d = 0.0;
    if (r >= 1)
      d += ndu[static_cast<size_t>(r - 1)][static_cast<size_t>(p - 1)] /
           ndu[static_cast<size_t>(p)][static_cast<size_t>(r - 1)];
    if (r <= p - 1)
      d -=
          ndu[static_cast<size_t>(r)][static_cast<size_t>(p - 1)] / ndu[static_cast<size_t>(p)][static_cast<size_t>(r)];
    dN[r] = p * d;
  }
}

}  // namespace

NurbsSurface validate_nurbs(const NurbsSurface& s, const std::string& name) {
  for (const auto& [degree, count, dir] :
       {std::tuple{s.degree_u, s.count_u, "u"}, std::tuple{s.degree_v, s.count_v, "v"}}) {
    if (degree < 1 || degree > kMaxNurbsDegree)
      throw InputError(name + ": degree " + std::to_string(degree) + " in " + dir + " is not between 1 and " +
                       std::to_string(kMaxNurbsDegree));
    if (count < degree + 1)
      throw InputError(name + ": " + std::to_string(count) + " control points in " + dir + " are too few for degree " +
                       std::to_string(degree));
    if (count > kMaxNurbsControlPoints) throw InputError(name + ": too many control points in " + dir);
  }
  if (static_cast<long long>(s.count_u) * s.count_v > kMaxNurbsControlPoints)
    throw InputError(name + ": " + std::to_string(static_cast<long long>(s.count_u) * s.count_v) +
                     " control points are more than this page takes (" + std::to_string(kMaxNurbsControlPoints) + ")");
  const size_t n = static_cast<size_t>(s.count_u) * static_cast<size_t>(s.count_v);
  if (s.points.size() != n)
    throw InputError(name + ": " + std::to_string(s.points.size()) + " control points given, " +
                     std::to_string(s.count_u) + " x " + std::to_string(s.count_v) + " expected");
  if (!s.weights.empty() && s.weights.size() != n)
    throw InputError(name + ": " + std::to_string(s.weights.size()) + " weights for " + std::to_string(n) +
                     " control points");
  NurbsSurface out = s;
  out.knots_u = textbook_knots(s.knots_u, s.count_u, s.degree_u, name + ": u");
  out.knots_v = textbook_knots(s.knots_v, s.count_v, s.degree_v, name + ": v");
  for (size_t k = 0; k < n; ++k)
    if (!s.points[k].allFinite()) throw InputError(name + ": control point " + std::to_string(k) + " is not finite");
  if (out.weights.empty()) out.weights.assign(n, 1.0);
  for (size_t k = 0; k < n; ++k)
    if (!(std::isfinite(out.weights[k]) && out.weights[k] > 0.0))
      throw InputError(name + ": weight " + std::to_string(k) + " is not positive and finite");
  return out;
}

NurbsDomain nurbs_domain(const NurbsSurface& s) {
  return {s.knots_u[static_cast<size_t>(s.degree_u)], s.knots_u[static_cast<size_t>(s.count_u)],
          s.knots_v[static_cast<size_t>(s.degree_v)], s.knots_v[static_cast<size_t>(s.count_v)]};
}

std::vector<double> nurbs_breaks(const NurbsSurface& s, bool along_u) {
  const std::vector<double>& U = along_u ? s.knots_u : s.knots_v;
  const int p = along_u ? s.degree_u : s.degree_v;
  const int count = along_u ? s.count_u : s.count_v;
  std::vector<double> out;
  for (int k = p; k <= count; ++k)
    if (out.empty() || U[static_cast<size_t>(k)] > out.back()) out.push_back(U[static_cast<size_t>(k)]);
  return out;
}

NurbsPoint evaluate_nurbs(const NurbsSurface& s, double u, double v) {
  const NurbsDomain d = nurbs_domain(s);
  u = std::clamp(u, d.u0, d.u1);
  v = std::clamp(v, d.v0, d.v1);
  const int pu = s.degree_u, pv = s.degree_v;
  const int su = find_span(s.knots_u, s.count_u, pu, u);
  const int sv = find_span(s.knots_v, s.count_v, pv, v);
  std::array<double, kMaxNurbsDegree + 1> Nu{}, dNu{}, Nv{}, dNv{};
  basis_and_derivative(s.knots_u, su, pu, u, Nu.data(), dNu.data());
  basis_and_derivative(s.knots_v, sv, pv, v, Nv.data(), dNv.data());
  // Homogeneous sums: A = sum N w P, W = sum N w, and their u / v derivatives.
  Vec3 A = Vec3::Zero(), Au = Vec3::Zero(), Av = Vec3::Zero();
  double W = 0.0, Wu = 0.0, Wv = 0.0;
  for (int k = 0; k <= pu; ++k) {
    for (int l = 0; l <= pv; ++l) {
      const size_t idx =
          static_cast<size_t>(su - pu + k) * static_cast<size_t>(s.count_v) + static_cast<size_t>(sv - pv + l);
      const double w = s.weights[idx];
      const Vec3 wp = w * s.points[idx];
      const double b = Nu[static_cast<size_t>(k)] * Nv[static_cast<size_t>(l)];
      const double bu = dNu[static_cast<size_t>(k)] * Nv[static_cast<size_t>(l)];
      const double bv = Nu[static_cast<size_t>(k)] * dNv[static_cast<size_t>(l)];
      A += b * wp;
      Au += bu * wp;
      Av += bv * wp;
      W += b * w;
      Wu += bu * w;
      Wv += bv * w;
    }
  }
  NurbsPoint out;
  out.p = A / W;
  out.du = (Au - Wu * out.p) / W;
  out.dv = (Av - Wv * out.p) / W;
  return out;
}

}  // namespace ff
