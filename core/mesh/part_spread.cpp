#include "core/mesh/part_spread.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "core/mesh/half_edges.h"
#include "core/mesh/manifold_part.h"
#include "core/util/error.h"
#include "core/util/short_number.h"
#include "core/util/union_find.h"

namespace ff {
namespace {

struct Part {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -Vec3::Constant(std::numeric_limits<double>::infinity());
  int triangles = 0;
  double diagonal() const { return triangles > 0 ? (hi - lo).norm() : 0.0; }
  Vec3 middle() const { return 0.5 * (lo + hi); }
};

}  // namespace

std::vector<int> vertex_part_roots(const TriMesh& mesh) {
  std::vector<int> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (size_t i = 1; i < 3; ++i) {
      const int a = union_find_root(parent, t[0]), b = union_find_root(parent, t[i]);
      if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = union_find_root(parent, static_cast<int>(v));
  return parent;
}

void require_compact_parts(const TriMesh& mesh) { require_compact_parts(mesh, vertex_part_roots(mesh)); }

void require_compact_parts(const TriMesh& mesh, const std::vector<int>& root) {
  const double whole = bbox_diagonal(mesh);
  if (!(whole > 0.0) || mesh.triangles.empty()) return;
  std::vector<Part> parts(mesh.positions.size());
  for (const Triangle& t : mesh.triangles) {
    Part& part = parts[static_cast<size_t>(root[static_cast<size_t>(t[0])])];
    ++part.triangles;
    for (const int v : t) {
      part.lo = part.lo.cwiseMin(mesh.positions[static_cast<size_t>(v)]);
      part.hi = part.hi.cwiseMax(mesh.positions[static_cast<size_t>(v)]);
    }
  }
  // The model is the part with the most triangles (ties: the larger): a stray triangle can be
  // larger than the model itself (one corner typed 1e6 away), and measured from it the model
  // looked close.
  size_t largest = 0;
  for (size_t p = 0; p < parts.size(); ++p) {
    const Part &a = parts[p], &b = parts[largest];
    if (a.triangles > b.triangles || (a.triangles == b.triangles && a.diagonal() > b.diagonal())) largest = p;
  }
  const double size = parts[largest].diagonal();
  if (!(size > 0.0) || !(whole > kMaxPartSpread * size)) return;
  size_t farthest = largest;
  double distance = 0.0;
  for (size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].triangles == 0) continue;
    const double d = (parts[p].middle() - parts[largest].middle()).norm();
    if (d > distance) distance = d, farthest = p;
  }
  const Part& far = parts[farthest];
  const std::string message = "a part of " + std::to_string(far.triangles) +
                              (far.triangles == 1 ? " triangle" : " triangles") + " near " +
                              detail::format_point(far.middle()) + " lies " + short_number(distance / size) +
                              " times the main part's size (" + short_number(size) +
                              ", the part with the most triangles) away from it: a stray piece? The mesh may span "
                              "at most " +
                              short_number(kMaxPartSpread) + " times its main part; delete the far-off part";
  // What keeping the largest part would keep: the part of largest area (manifold_part.h).
  const size_t kept = detail::largest_manifold_part(mesh.triangles, mesh.positions).faces.size();
  throw LargestPartError(message, static_cast<int>(kept), static_cast<int>(mesh.triangles.size()));
}

}  // namespace ff
