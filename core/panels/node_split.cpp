#include "core/panels/node_split.h"

#include <algorithm>

namespace ff {

namespace {

// All triangulations of the polygon i..j (positions i < j, consecutive).
std::vector<Pairing> triangulations(int i, int j) {
  if (j - i < 2) return {Pairing{}};
  std::vector<Pairing> out;
  for (int m = i + 1; m < j; ++m) {
    const std::vector<Pairing> left = triangulations(i, m);
    const std::vector<Pairing> right = triangulations(m, j);
    for (const Pairing& l : left) {
      for (const Pairing& r : right) {
        Pairing p = l;
        p.insert(p.end(), r.begin(), r.end());
        p.push_back({i, m, j});
        out.push_back(std::move(p));
      }
    }
  }
  return out;
}

Pairing fan_from(int k, int apex) {
  Pairing p;
  for (int t = 1; t + 1 < k; ++t) {
    NodeTriangle tri{apex, (apex + t) % k, (apex + t + 1) % k};
    std::sort(tri.begin(), tri.end());
    p.push_back(tri);
  }
  return p;
}

}  // namespace

std::vector<Pairing> node_pairings(int k) {
  if (k <= 7) return triangulations(0, k - 1);
  std::vector<Pairing> out;
  for (int apex = 0; apex < k; ++apex) out.push_back(fan_from(k, apex));
  return out;
}

Pairing fan_pairing(int k) { return fan_from(k, k - 1); }

std::vector<int> triangles_around(const Pairing& pairing, int k, int i) {
  std::vector<int> out;
  triangles_around(pairing, k, i, out);
  return out;
}

void triangles_around(const Pairing& pairing, int k, int i, std::vector<int>& out) {
  // Order by the offset (mod k) of the triangle's other two positions from i: the triangle
  // through i+1 has the smallest, the one through i-1 the largest. The offsets are distinct
  // (a pairing is a triangulation), so an insertion sort by them gives that order.
  const auto offset = [&](int t) {
    int lo = k;
    for (int p : pairing[static_cast<size_t>(t)]) {
      if (p != i) lo = std::min(lo, ((p - i) % k + k) % k);
    }
    return lo;
  };
  out.clear();
  for (size_t t = 0; t < pairing.size(); ++t) {
    const NodeTriangle& tri = pairing[t];
    if (tri[0] != i && tri[1] != i && tri[2] != i) continue;
    const int key = offset(static_cast<int>(t));
    size_t at = out.size();
    out.push_back(static_cast<int>(t));
    for (; at > 0 && offset(out[at - 1]) > key; --at) out[at] = out[at - 1];
    out[at] = static_cast<int>(t);
  }
}

bool hold_pairings(const std::vector<int>& clusters, const std::vector<std::array<int, 3>>& held,
                   std::vector<Pairing>& options) {
  std::vector<std::array<int, 3>> wanted;
  for (const std::array<int, 3>& t : held) {
    const auto in = [&](int c) { return std::find(clusters.begin(), clusters.end(), c) != clusters.end(); };
    if (in(t[0]) && in(t[1]) && in(t[2])) wanted.push_back(t);
  }
  if (wanted.empty()) return false;
  std::vector<Pairing> kept;
  for (const Pairing& p : options) {
    std::vector<std::array<int, 3>> nodes;
    for (const NodeTriangle& tri : p) {
      std::array<int, 3> t{clusters[static_cast<size_t>(tri[0])], clusters[static_cast<size_t>(tri[1])],
                           clusters[static_cast<size_t>(tri[2])]};
      std::sort(t.begin(), t.end());
      nodes.push_back(t);
    }
    const auto has = [&](const std::array<int, 3>& t) { return std::find(nodes.begin(), nodes.end(), t) != nodes.end(); };
    if (std::all_of(wanted.begin(), wanted.end(), has)) kept.push_back(p);
  }
  if (kept.empty()) return false;
  options = std::move(kept);
  return true;
}


}  // namespace ff
