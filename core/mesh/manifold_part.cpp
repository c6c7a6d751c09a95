#include "core/mesh/manifold_part.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/mesh/half_edges.h"
#include "core/mesh/part_spread.h"
#include "core/util/union_find.h"

namespace ff::detail {

ManifoldPart largest_manifold_part(const std::vector<Triangle>& tris, const std::vector<Vec3>& positions) {
  ManifoldPart result;
  const int n = static_cast<int>(positions.size());
  std::vector<int> faces(tris.size());  // the current selection, as indices into tris
  std::iota(faces.begin(), faces.end(), 0);
  for (bool first_round = true;; first_round = false) {
    std::vector<Triangle> sub(faces.size());
    for (size_t k = 0; k < faces.size(); ++k) sub[k] = tris[static_cast<size_t>(faces[k])];
    const HalfEdgeGroups groups = group_half_edges(sub, n);
    std::vector<char> drop(sub.size(), 0);
    int bad = 0;
    for (int g = 0; g < groups.num_groups(); ++g) {
      if (groups.group_size(g) < 3) continue;
      ++bad;
      // Past the first round: the kept sheet wraps onto this edge; keep two of its faces.
      if (!first_round) {
        for (int i = groups.group_start[static_cast<size_t>(g)] + 2; i < groups.group_start[static_cast<size_t>(g) + 1]; ++i)
          drop[static_cast<size_t>(groups.order[static_cast<size_t>(i)] / 3)] = 1;
      }
    }
    if (first_round) result.nonmanifold_edges = bad;
    if (bad == 0 && !first_round) break;  // the first round splits a manifold mesh into its parts

    std::vector<int> parent(sub.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (int g = 0; g < groups.num_groups(); ++g) {
      if (groups.group_size(g) != 2) continue;
      const int fa = groups.first(g) / 3, fb = groups.second(g) / 3;
      if (drop[static_cast<size_t>(fa)] || drop[static_cast<size_t>(fb)]) continue;
      const int a = union_find_root(parent, fa), b = union_find_root(parent, fb);
      if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
    }
    // Per sheet (at its root): area, faces and bounding box.
    std::vector<double> area(sub.size(), 0.0);
    std::vector<int> count(sub.size(), 0);
    std::vector<Vec3> lo(sub.size(), Vec3::Constant(std::numeric_limits<double>::infinity()));
    std::vector<Vec3> hi(sub.size(), -Vec3::Constant(std::numeric_limits<double>::infinity()));
    int sheets = 0;
    for (size_t f = 0; f < sub.size(); ++f) {
      if (drop[f]) continue;
      const auto r = static_cast<size_t>(union_find_root(parent, static_cast<int>(f)));
      const Vec3& a = positions[static_cast<size_t>(sub[f][0])];
      area[r] += 0.5 * (positions[static_cast<size_t>(sub[f][1])] - a).cross(positions[static_cast<size_t>(sub[f][2])] - a).norm();
      sheets += count[r]++ == 0 ? 1 : 0;
      for (const int v : sub[f]) {
        lo[r] = lo[r].cwiseMin(positions[static_cast<size_t>(v)]);
        hi[r] = hi[r].cwiseMax(positions[static_cast<size_t>(v)]);
      }
    }
    if (first_round) result.sheets = sheets;
    // A sheet more than kMaxPartSpread times the size of the sheet with the most faces is a
    // stray piece (a triangle with a corner typed 1e6 away), however large its area: not kept.
    int most = -1;
    for (size_t r = 0; r < sub.size(); ++r) {
      if (count[r] > 0 && (most < 0 || count[r] > count[static_cast<size_t>(most)])) most = static_cast<int>(r);
    }
    const auto diagonal = [&](size_t r) { return (hi[r] - lo[r]).norm(); };
    const double sane = most < 0 ? 0.0 : kMaxPartSpread * diagonal(static_cast<size_t>(most));
    // Roots are the lowest face of their sheet, so scanning up breaks ties by it.
    int best = -1;
    for (size_t r = 0; r < sub.size(); ++r) {
      if (count[r] == 0 || diagonal(r) > sane) continue;
      const auto b = static_cast<size_t>(best);
      if (best < 0 || area[r] > area[b] || (area[r] == area[b] && count[r] > count[b])) best = static_cast<int>(r);
    }
    if (first_round) {
      for (size_t r = 0; r < sub.size(); ++r) {
        if (static_cast<int>(r) != best) result.most_faces_left_out = std::max(result.most_faces_left_out, count[r]);
      }
    }
    std::vector<int> kept;
    for (size_t f = 0; f < sub.size(); ++f) {
      if (!drop[f] && union_find_root(parent, static_cast<int>(f)) == best) kept.push_back(faces[f]);
    }
    faces = std::move(kept);
  }
  result.faces = std::move(faces);
  return result;
}

}  // namespace ff::detail
