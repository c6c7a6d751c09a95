#include "core/mesh/fill_holes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/mesh/half_edges.h"
#include "core/mesh/slivers.h"

namespace ff::detail {

namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

// Least-area triangulation of the polygon loop[0..k) (Liepa's dynamic program without the
// dihedral term), first with the fewest slivers: straight runs of boundary would otherwise
// get zero-area triangles, the least area of all. Appends faces reversed against the loop (the loop runs with its faces);
// false when every triangulation would repeat an existing edge.
bool triangulate(const std::vector<int>& loop, const std::vector<Vec3>& positions,
                 const std::vector<std::uint64_t>& edges, std::vector<Triangle>& out) {
  const size_t k = loop.size();
  const auto pos = [&](size_t i) -> const Vec3& { return positions[static_cast<size_t>(loop[i])]; };
  // A diagonal may not be an edge already (that would make it non-manifold).
  const auto usable = [&](size_t i, size_t j) {
    if (j == i + 1 || (i == 0 && j == k - 1)) return true;
    return !std::binary_search(edges.begin(), edges.end(), edge_key(loop[i], loop[j]));
  };
  const double inf = std::numeric_limits<double>::infinity();
  const double diag = [&] {
    Vec3 lo = pos(0), hi = pos(0);
    for (size_t i = 1; i < k; ++i) lo = lo.cwiseMin(pos(i)), hi = hi.cwiseMax(pos(i));
    return (hi - lo).norm();
  }();
  std::vector<double> cost(k * k, inf);
  std::vector<int> slivers(k * k, 0);
  std::vector<int> best(k * k, -1);
  for (size_t i = 0; i + 1 < k; ++i) cost[i * k + i + 1] = 0.0;
  for (size_t len = 2; len < k; ++len) {
    for (size_t i = 0; i + len < k; ++i) {
      const size_t j = i + len;
      if (!usable(i, j)) continue;
      for (size_t m = i + 1; m < j; ++m) {
        const double sub = cost[i * k + m] + cost[m * k + j];
        if (!(sub < inf)) continue;
        const double c = sub + 0.5 * (pos(m) - pos(i)).cross(pos(j) - pos(i)).norm();
        const int s = slivers[i * k + m] + slivers[m * k + j] + (is_sliver(pos(i), pos(m), pos(j), diag) ? 1 : 0);
        const size_t ij = i * k + j;
        if (cost[ij] == inf || s < slivers[ij] || (s == slivers[ij] && c < cost[ij])) {
          cost[ij] = c;
          slivers[ij] = s;
          best[i * k + j] = static_cast<int>(m);
        }
      }
    }
  }
  if (!(cost[k - 1] < inf)) return false;
  std::vector<std::pair<size_t, size_t>> stack = {{0, k - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j < i + 2) continue;
    const auto m = static_cast<size_t>(best[i * k + j]);
    out.push_back({loop[j], loop[m], loop[i]});
    stack.push_back({m, j});
    stack.push_back({i, m});
  }
  return true;
}

}  // namespace

HoleFill fill_holes(std::vector<Triangle>& tris, const std::vector<Vec3>& positions, int max_edges,
                    std::vector<int>& face_origin) {
  HoleFill result;
  const int n = static_cast<int>(positions.size());
  const HalfEdgeGroups groups = group_half_edges(tris, n);
  std::vector<std::uint64_t> edges;
  edges.reserve(static_cast<size_t>(groups.num_groups()));
  // Boundary half-edge leaving each vertex (at most one: no non-manifold vertices).
  std::vector<int> leaving(static_cast<size_t>(n), -1);
  std::vector<int> boundary;
  for (int g = 0; g < groups.num_groups(); ++g) {
    const int h = groups.first(g);
    edges.push_back(edge_key(tail_of(tris, h), head_of(tris, h)));
    if (groups.group_size(g) != 1) continue;
    leaving[static_cast<size_t>(tail_of(tris, h))] = h;
    boundary.push_back(h);
  }
  std::sort(edges.begin(), edges.end());
  std::sort(boundary.begin(), boundary.end());  // loops in face order: deterministic

  std::vector<char> seen(3 * tris.size(), 0);
  // A new diagonal joins two corners of one loop and no vertex is on two loops, so holes
  // cannot add the same edge: `edges` needs no update while filling.
  for (int start : boundary) {
    if (seen[static_cast<size_t>(start)]) continue;
    std::vector<int> loop;
    bool closed = false;
    for (int h = start; h >= 0 && !seen[static_cast<size_t>(h)];) {
      seen[static_cast<size_t>(h)] = 1;
      loop.push_back(tail_of(tris, h));
      h = leaving[static_cast<size_t>(head_of(tris, h))];
      closed = h == start;
    }
    if (!closed || static_cast<int>(loop.size()) > max_edges || loop.size() < 3) {
      ++result.holes_left;
      continue;
    }
    std::vector<Triangle> added;
    if (!triangulate(loop, positions, edges, added)) {
      ++result.holes_left;
      continue;
    }
    for (const Triangle& t : added) {
      tris.push_back(t);
      face_origin.push_back(start / 3);
    }
    ++result.holes_filled;
    result.faces_added += static_cast<int>(added.size());
  }
  return result;
}

}  // namespace ff::detail
