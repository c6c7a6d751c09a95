#include "core/panels/plane_relax.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/panels/sym_eigen3_newton.h"

namespace ff {

namespace {

// Eigen's LDLT<Matrix3d>(A).solve(b) step for step: the same pivots and the same operations
// in the same order (so the same bits, which the chaotic panel phase needs to stay as it
// was), without the generic machinery around them: the node solve runs once per node and
// iteration, up to 80 times per relaxation. Eigen 3.4, LDLT.h: ldlt_inplace<Lower>::unblocked
// and _solve_impl_transposed (unrolled triangular solves). The six entries of A's lower
// triangle are plain variables and the pivoting swaps them by name, so they stay in
// registers (an array indexed by the pivot lived on the stack, and its mixed-width loads and
// stores stalled).
struct Lower3 {
  double d0, d1, d2;     // diagonal (D after factorisation)
  double l10, l20, l21;  // below it (L after factorisation)
};

Vec3 ldlt_solve3(Lower3 m, double y0, double y1, double y2) {
  int t0 = 0, t1 = 1;  // the transpositions of steps 0 and 1 (step 2 has none)
  // Step 0: the largest diagonal entry (the first on ties) to the front.
  double best = std::abs(m.d0);
  if (std::abs(m.d1) > best) best = std::abs(m.d1), t0 = 1;
  if (std::abs(m.d2) > best) t0 = 2;
  if (t0 == 1) {
    std::swap(m.d0, m.d1);
    std::swap(m.l20, m.l21);
  } else if (t0 == 2) {
    std::swap(m.d0, m.d2);
    std::swap(m.l10, m.l21);
  }
  if (std::abs(m.d0) > 0.0) {  // a zero first pivot: Eigen stops here with no transpositions
    m.l10 /= m.d0;
    m.l20 /= m.d0;
    // Step 1.
    if (std::abs(m.d2) > std::abs(m.d1)) {
      t1 = 2;
      std::swap(m.l10, m.l20);
      std::swap(m.d1, m.d2);
    }
    const double temp0 = m.d0 * m.l10;
    m.d1 -= m.l10 * temp0;
    m.l21 -= m.l20 * temp0;
    if (std::abs(m.d1) > 0.0) m.l21 /= m.d1;
    // Step 2.
    const double u0 = m.d0 * m.l20, u1 = m.d1 * m.l21;
    m.d2 -= m.l20 * u0 + m.l21 * u1;
  } else {
    t0 = 0;
  }
  if (t0 == 1) std::swap(y0, y1);
  if (t0 == 2) std::swap(y0, y2);
  if (t1 == 2) std::swap(y1, y2);
  y1 -= m.l10 * y0;
  y2 -= m.l20 * y0 + m.l21 * y1;
  constexpr double kTiny = std::numeric_limits<double>::min();
  y0 = std::abs(m.d0) > kTiny ? y0 / m.d0 : 0.0;
  y1 = std::abs(m.d1) > kTiny ? y1 / m.d1 : 0.0;
  y2 = std::abs(m.d2) > kTiny ? y2 / m.d2 : 0.0;
  y1 -= m.l21 * y2;
  y0 -= m.l10 * y1 + m.l20 * y2;
  if (t1 == 2) std::swap(y1, y2);
  if (t0 == 2) std::swap(y0, y2);
  if (t0 == 1) std::swap(y0, y1);
  return Vec3(y0, y1, y2);
}

// A plane's part of its nodes' solves at the current W: W n n^T (lower triangle, row by
// row) and W d n.
struct PlaneTerms {
  double a[6];
  double b[3];
};

bool hinged(const std::vector<PlaneHinge>& hinges, size_t i) { return i < hinges.size() && hinges[i].on; }

// True when no plane of `moving` moved by more than options.settled_step from `before` (the
// same planes in the same order) to `planes`, in its normal or its offset (the planes live
// in FaceData's local frame, where the mesh is about 1 across); `planes` then get the rest of
// the geometric series added (RelaxOptions). A NaN step is not settled. A plane is
// extrapolated as the 4-vector (normal, offset) and scaled back to a unit normal, so a hinged
// plane stays through its hinge point.
bool settled(const std::vector<Plane>& before, std::vector<Plane>& planes, const std::vector<size_t>& moving,
             const RelaxOptions& options) {
  for (size_t j = 0; j < moving.size(); ++j) {
    const Plane& now = planes[moving[j]];
    if (!((now.normal - before[j].normal).lpNorm<Eigen::Infinity>() <= options.settled_step)) return false;
    if (!(std::abs(now.offset - before[j].offset) <= options.settled_step)) return false;
  }
  const double tail = 1.0 / (options.growth - 1.0);
  for (size_t j = 0; j < moving.size(); ++j) {
    Plane& plane = planes[moving[j]];
    const Vec3 normal = plane.normal + tail * (plane.normal - before[j].normal);
    const double offset = plane.offset + tail * (plane.offset - before[j].offset);
    const double length = normal.norm();
    if (length > 0.5 && std::isfinite(offset)) plane = Plane{normal / length, offset / length};
  }
  return true;
}

}  // namespace

Plane hinged_fit(const PlaneHinge& hinge, const Eigen::Matrix3d& scatter, const Plane& side) {
  const Vec3& u = hinge.direction;
  // Two unit vectors across the line: the normal is a combination of them, so it stays
  // perpendicular to the line and the plane keeps containing it.
  const Vec3 e1 = u.unitOrthogonal();
  const Vec3 e2 = u.cross(e1).normalized();
  Eigen::Matrix2d m;
  m(0, 0) = e1.dot(scatter * e1);
  m(1, 1) = e2.dot(scatter * e2);
  m(0, 1) = m(1, 0) = 0.5 * (e1.dot(scatter * e2) + e2.dot(scatter * e1));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(m);
  const Eigen::Vector2d c = solver.eigenvectors().col(0);
  Vec3 normal = c(0) * e1 + c(1) * e2;
  if (!normal.allFinite() || normal.norm() < 0.5) return side;
  normal.normalize();
  if (normal.dot(side.normal) < 0.0) normal = -normal;
  return Plane::through(hinge.point, normal);
}

std::vector<Plane> relax_planes(const std::vector<NodeConstraint>& nodes, const std::vector<ClusterMoments>& moments,
                                const std::vector<Plane>& start, const RelaxOptions& options,
                                const std::vector<char>& fixed, const std::vector<PlaneHinge>& hinges) {
  std::vector<Plane> planes = start;
  const size_t m = planes.size();
  // Per-plane node weight: node_weight * area / (its number of nodes).
  std::vector<int> node_count(m, 0);
  for (const NodeConstraint& k : nodes) {
    for (int i = 0; i < k.count; ++i) node_count[static_cast<size_t>(k.planes[static_cast<size_t>(i)])] += 1;
  }
  std::vector<double> node_weight(m, 0.0);
  for (size_t i = 0; i < m; ++i) {
    if (node_count[i] > 0) node_weight[i] = options.node_weight * moments[i].area / node_count[i];
  }
  std::vector<Vec3> x(nodes.size());
  // Nodes among fixed planes only cannot move anything: leave them out.
  std::vector<size_t> active;
  for (size_t k = 0; k < nodes.size(); ++k) {
    bool free = fixed.empty();
    for (int j = 0; j < nodes[k].count && !free; ++j)
      free = !fixed[static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)])];
    if (free) active.push_back(k);
  }
  // Which planes the iterations touch: the free ones (fitted) and every plane of an active
  // node (its terms enter the node's solve). With most planes fixed (the later panel rounds)
  // the loops below run over these lists only; the arithmetic per plane and per node is the
  // same, in the same order, so the result is the same to the bit.
  const auto is_fixed = [&](size_t i) { return !fixed.empty() && fixed[i]; };
  std::vector<char> used(m, 0);
  for (size_t k : active) {
    for (int j = 0; j < nodes[k].count; ++j) used[static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)])] = 1;
  }
  std::vector<size_t> termed, fitted;  // planes with node terms; planes fitted each iteration
  for (size_t i = 0; i < m; ++i) {
    if (used[i]) termed.push_back(i);
    if (!is_fixed(i)) fitted.push_back(i);
  }
  // Per active node, its free planes (the only ones whose sums are read).
  std::vector<int> free_offset(1, 0), free_plane;
  for (size_t k : active) {
    for (int j = 0; j < nodes[k].count; ++j) {
      const int i = nodes[k].planes[static_cast<size_t>(j)];
      if (!is_fixed(static_cast<size_t>(i))) free_plane.push_back(i);
    }
    free_offset.push_back(static_cast<int>(free_plane.size()));
  }
  std::vector<double> area(m), pull(m);
  std::vector<Vec3> first(m), center(m);
  std::vector<Eigen::Matrix3d> scatter(m);
  std::vector<PlaneTerms> terms(m);
  double w = options.start_weight;
  // W past which the nodes count as pinned to their planes (the settled stop's premise).
  double pinned_weight = 0.0;
  for (size_t k : active) pinned_weight = std::max(pinned_weight, 1e3 * nodes[k].weight);
  // The tail's sum is only worth adding where W grows fast enough for the series to end soon.
  const bool may_settle = options.settled_step > 0.0 && options.growth >= 1.1;
  std::vector<Plane> before(fitted.size());  // the fitted planes at the start of a settling iteration
  for (int it = 0; it < options.iterations; ++it, w *= options.growth) {
    const bool settling = may_settle && w >= pinned_weight;
    if (settling) {
      for (size_t j = 0; j < fitted.size(); ++j) before[j] = planes[fitted[j]];
    }
    // Nodes: minimise c_k |x - p|^2 + W sum_i (n_i.x - d_i)^2, c_k the node's own weight.
    // Each plane's W n n^T (lower triangle) and W d n once per iteration rather than once per
    // node: the same products, so the same bits as forming them per node.
    for (size_t i : termed) {
      const Vec3& n = planes[i].normal;
      const double wn[3] = {w * n.x(), w * n.y(), w * n.z()};
      const double wd = w * planes[i].offset;
      PlaneTerms& pt = terms[i];
      pt.a[0] = wn[0] * n.x();
      pt.a[1] = wn[1] * n.x(), pt.a[2] = wn[1] * n.y();
      pt.a[3] = wn[2] * n.x(), pt.a[4] = wn[2] * n.y(), pt.a[5] = wn[2] * n.z();
      pt.b[0] = wd * n.x(), pt.b[1] = wd * n.y(), pt.b[2] = wd * n.z();
    }
    for (size_t k : active) {
      const NodeConstraint& node = nodes[k];
      Lower3 a{node.weight, node.weight, node.weight, 0.0, 0.0, 0.0};
      double b0 = node.weight * node.corner.x(), b1 = node.weight * node.corner.y(), b2 = node.weight * node.corner.z();
      for (int j = 0; j < node.count; ++j) {
        const PlaneTerms& pt = terms[static_cast<size_t>(node.planes[static_cast<size_t>(j)])];
        a.d0 += pt.a[0];
        a.l10 += pt.a[1], a.d1 += pt.a[2];
        a.l20 += pt.a[3], a.l21 += pt.a[4], a.d2 += pt.a[5];
        b0 += pt.b[0], b1 += pt.b[1], b2 += pt.b[2];
      }
      x[k] = ldlt_solve3(a, b0, b1, b2);
    }
    // Planes: least squares over their faces (exact moments) and their nodes (weight W w_i),
    // the scatter formed about the common centre (two passes) to keep its precision at large W.
    // Only the free planes: a fixed one stays as it is, its sums are not needed.
    for (size_t i : fitted) area[i] = moments[i].area, first[i] = moments[i].first, pull[i] = w * node_weight[i];
    for (size_t a = 0; a < active.size(); ++a) {
      const Vec3& xk = x[active[a]];
      for (int j = free_offset[a]; j < free_offset[a + 1]; ++j) {
        const size_t i = static_cast<size_t>(free_plane[static_cast<size_t>(j)]);
        area[i] += pull[i];
        first[i] += pull[i] * xk;
      }
    }
    for (size_t i : fitted) {
      // A hinged plane's scatter is about its hinge point: the plane must pass through it.
      center[i] = hinged(hinges, i) ? hinges[i].point : area[i] > 0.0 ? Vec3(first[i] / area[i]) : Vec3::Zero();
      const ClusterMoments& mo = moments[i];
      const Vec3& c = center[i];
      // second - first c^T - c first^T + (area c) c^T, entry by entry with the products and
      // sums of Eigen's expression (no outer-product temporaries on the stack).
      const double ac[3] = {mo.area * c.x(), mo.area * c.y(), mo.area * c.z()};
      Eigen::Matrix3d& sc = scatter[i];
      for (int col = 0; col < 3; ++col) {
        for (int row = 0; row < 3; ++row)
          sc(row, col) = mo.second(row, col) - c(col) * mo.first(row) - mo.first(col) * c(row) + c(col) * ac[row];
      }
    }
    for (size_t a = 0; a < active.size(); ++a) {
      const Vec3& xk = x[active[a]];
      for (int j = free_offset[a]; j < free_offset[a + 1]; ++j) {
        const size_t i = static_cast<size_t>(free_plane[static_cast<size_t>(j)]);
        const Vec3 d = xk - center[i];
        // scatter += (pull d) d^T entry by entry, the same products as Eigen's outer product:
        // its temporary on the stack, written in halves and read whole, stalled every load.
        const double pd[3] = {pull[i] * d.x(), pull[i] * d.y(), pull[i] * d.z()};
        Eigen::Matrix3d& sc = scatter[i];
        for (int col = 0; col < 3; ++col) {
          for (int row = 0; row < 3; ++row) sc(row, col) += pd[row] * d(col);
        }
      }
    }
    const auto set_normal = [&](size_t i, Vec3 normal) {
      if (!normal.allFinite() || normal.norm() < 0.5) return;
      if (normal.dot(planes[i].normal) < 0.0) normal = -normal;
      planes[i] = Plane::through(center[i], normal.normalized());
    };
    // The characteristic cubic's smallest root (sym_eigen3_newton.h): Eigen's axis to
    // rounding at a ninth of its iterative solver's cost; two planes at a time (each plane's
    // result is its own, so the pairing changes no bit), each started from its last normal
    // (a plane turns little per iteration: about half the Newton steps).
    constexpr size_t kNone = static_cast<size_t>(-1);
    size_t waiting = kNone;
    Eigen::Matrix3d waiting_scatter;
    for (size_t i : fitted) {
      if (!(area[i] > 0.0)) continue;
      const Eigen::Matrix3d symmetric = 0.5 * (scatter[i] + scatter[i].transpose());
      if (hinged(hinges, i)) {
        planes[i] = hinged_fit(hinges[i], symmetric, planes[i]);
        continue;
      }
      if (waiting == kNone) {
        waiting = i;
        waiting_scatter = symmetric;
        continue;
      }
      Vec3 first_normal, second_normal;
      smallest_eigenvectors_newton(waiting_scatter, symmetric, first_normal, second_normal, &planes[waiting].normal,
                                   &planes[i].normal);
      set_normal(waiting, first_normal);
      set_normal(i, second_normal);
      waiting = kNone;
    }
    if (waiting != kNone) set_normal(waiting, smallest_eigenvector_newton(waiting_scatter, &planes[waiting].normal));
    if (settling && settled(before, planes, fitted, options)) break;
  }
  return planes;
}

}  // namespace ff
