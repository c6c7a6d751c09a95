#include "core/mesh/half_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "core/util/error.h"

namespace ff::detail {

namespace {
std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out << x;
  return out.str();
}
}  // namespace

std::string format_point(const Vec3& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) + ")";
}

void require_valid_indices(const std::vector<Triangle>& tris, int num_vertices, bool require_distinct) {
  // Half-edge ids are ints.
  if (tris.size() > static_cast<size_t>(std::numeric_limits<int>::max() / 3)) {
    throw InputError("the mesh has too many faces (" + std::to_string(tris.size()) + ")");
  }
  for (size_t f = 0; f < tris.size(); ++f) {
    const Triangle& t = tris[f];
    for (int v : t) {
      if (v < 0 || v >= num_vertices) {
        throw InputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                         ", but the mesh has only " + std::to_string(num_vertices) + " vertices (numbered from 0)");
      }
    }
    if (require_distinct && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])) {
      const int repeated = t[0] == t[1] || t[0] == t[2] ? t[0] : t[1];
      throw InputError("face " + std::to_string(f) + " uses vertex " + std::to_string(repeated) +
                       " twice (a degenerate triangle; clean the mesh first)");
    }
  }
}

HalfEdgeGroups group_half_edges(const std::vector<Triangle>& tris, int num_vertices) {
  const size_t num_half = tris.size() * 3;
  const size_t n = static_cast<size_t>(num_vertices);

  // Bucket half-edges by their smaller vertex (counting sort).
  std::vector<int> start(n + 1, 0);
  for (size_t h = 0; h < num_half; ++h) {
    const int a = tail_of(tris, static_cast<int>(h)), b = head_of(tris, static_cast<int>(h));
    ++start[static_cast<size_t>(std::min(a, b)) + 1];
  }
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];

  // Within a bucket, sort by (larger vertex, half-edge id) packed into one integer.
  std::vector<std::uint64_t> keyed(num_half);
  {
    std::vector<int> cursor(start.begin(), start.end() - 1);
    for (size_t h = 0; h < num_half; ++h) {
      const int a = tail_of(tris, static_cast<int>(h)), b = head_of(tris, static_cast<int>(h));
      const auto hi = static_cast<std::uint64_t>(std::max(a, b));
      keyed[static_cast<size_t>(cursor[static_cast<size_t>(std::min(a, b))]++)] = (hi << 32) | h;
    }
  }

  HalfEdgeGroups groups;
  groups.order.resize(num_half);
  groups.edge_of.resize(num_half);
  groups.group_start.reserve(num_half / 2 + 2);
  for (size_t v = 0; v < n; ++v) {
    const auto begin = keyed.begin() + start[v], end = keyed.begin() + start[v + 1];
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it) {
      if (it == begin || (*it >> 32) != (*(it - 1) >> 32)) {
        groups.group_start.push_back(static_cast<int>(it - keyed.begin()));
      }
      const auto k = static_cast<size_t>(it - keyed.begin());
      const int h = static_cast<int>(*it & 0xffffffffu);
      groups.order[k] = h;
      groups.edge_of[static_cast<size_t>(h)] = static_cast<int>(groups.group_start.size()) - 1;
    }
  }
  groups.group_start.push_back(static_cast<int>(num_half));
  return groups;
}

void require_edge_manifold(const HalfEdgeGroups& groups, const std::vector<Triangle>& tris,
                           const std::vector<Vec3>& positions, const std::vector<int>& vertex_name) {
  int first = -1, count = 0;
  for (int g = 0; g < groups.num_groups(); ++g) {
    if (groups.group_size(g) < 3) continue;
    if (first < 0) first = g;
    ++count;
  }
  if (first < 0) return;

  const int h = groups.first(first);
  const int a = std::min(tail_of(tris, h), head_of(tris, h));
  const int b = std::max(tail_of(tris, h), head_of(tris, h));
  const auto name = [&](int v) {
    return std::to_string(vertex_name.empty() ? v : vertex_name[static_cast<size_t>(v)]);
  };
  const Vec3 mid = 0.5 * (positions[static_cast<size_t>(a)] + positions[static_cast<size_t>(b)]);
  std::string message = "non-manifold edge between vertices " + name(a) + " and " + name(b) + " at " +
                        format_point(mid) + ": shared by " + std::to_string(groups.group_size(first)) + " faces";
  if (count > 1) {
    message += " (and " + std::to_string(count - 1) + " more non-manifold edge" + (count > 2 ? "s" : "") + ")";
  }
  throw InputError(message);
}

}  // namespace ff::detail
