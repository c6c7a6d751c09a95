#include "core/mesh/vertex_spread.h"

#include <algorithm>
#include <string>

#include "core/mesh/half_edges.h"
#include "core/mesh/part_spread.h"
#include "core/util/error.h"
#include "core/util/short_number.h"

namespace ff {
namespace {

// The k-th smallest of values (a copy: nth_element reorders).
double kth_smallest(std::vector<double> values, size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

struct Spread {
  Vec3 middle = Vec3::Zero();  // per-axis median
  double bulk = 0.0;           // 90% of the vertices lie within this of the middle
  size_t farthest = 0;         // a mesh vertex
  double reach = 0.0;          // its distance from the middle
  int stray = 0;               // vertices beyond kMaxVertexSpread * bulk
  double ratio() const { return bulk > 0.0 ? reach / bulk : 0.0; }
};

// The spread of one part's vertices (at least 4).
Spread spread_of(const std::vector<Vec3>& positions, const std::vector<size_t>& part) {
  Spread s;
  const size_t n = part.size();
  std::vector<double> values(n);
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t i = 0; i < n; ++i) values[i] = positions[part[i]][axis];
    s.middle[axis] = kth_smallest(values, n / 2);
  }
  for (size_t i = 0; i < n; ++i) {
    values[i] = (positions[part[i]] - s.middle).stableNorm();  // a model 1e154 across: no inf
    if (values[i] > s.reach) s.reach = values[i], s.farthest = part[i];
  }
  s.bulk = kth_smallest(values, (n - 1) * 9 / 10);
  for (const double d : values) s.stray += d > kMaxVertexSpread * s.bulk ? 1 : 0;
  return s;
}

}  // namespace

void require_no_stray_vertex(const TriMesh& mesh, const std::vector<int>& vertex_source) {
  require_no_stray_vertex(mesh, vertex_source, vertex_part_roots(mesh));
}

void require_no_stray_vertex(const TriMesh& mesh, const std::vector<int>& vertex_source,
                             const std::vector<int>& root) {
  // Part by part: a small part far from the rest is part_spread.h's to name (and to offer
  // the largest part for); here each part is measured against itself.
  std::vector<std::vector<size_t>> parts(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) parts[static_cast<size_t>(root[v])].push_back(v);
  Spread worst;
  int nonempty_parts = 0;
  for (const std::vector<size_t>& part : parts) {
    nonempty_parts += part.empty() ? 0 : 1;
    if (part.size() < 4) continue;
    const Spread s = spread_of(mesh.positions, part);
    if (s.ratio() > worst.ratio()) worst = s;
  }
  if (!(worst.ratio() > kMaxVertexSpread)) return;
  const int name =
      worst.farthest < vertex_source.size() ? vertex_source[worst.farthest] : static_cast<int>(worst.farthest);
  const std::string whole = nonempty_parts == 1 ? "the mesh" : "its part";
  const std::string others = worst.stray > 1 ? " (and " + std::to_string(worst.stray - 1) +
                                                   (worst.stray == 2 ? " other vertex" : " other vertices") + ")"
                                             : "";
  throw InputError("vertex " + std::to_string(name) + " at " + detail::format_point(mesh.positions[worst.farthest]) +
                   others + " lies " + short_number(worst.ratio()) + " times farther from the middle of " + whole +
                   " " + detail::format_point(worst.middle) + " than 90% of " + whole + "'s vertices (within " +
                   short_number(worst.bulk) + "): a mistyped or corrupted coordinate? A vertex may lie at most " +
                   short_number(kMaxVertexSpread) + " times as far out; fix or delete it");
}

}  // namespace ff
