#include "core/panels/corner_groups.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace ff {

namespace {

struct Chain {
  double length;
  int from, to;  // corners
  int a, b;      // the clusters on either side
  bool operator<(const Chain& o) const {
    if (length != o.length) return length < o.length;
    return from != o.from ? from < o.from : to < o.to;
  }
};

// The position i with cycle[i] == u and cycle[i + 1] == v (cyclically), or -1.
int find_pair(const std::vector<int>& cycle, int u, int v) {
  const int k = static_cast<int>(cycle.size());
  int found = -1;
  for (int i = 0; i < k; ++i) {
    if (cycle[static_cast<size_t>(i)] == u && cycle[static_cast<size_t>((i + 1) % k)] == v) {
      if (found >= 0) return -1;  // twice: leave such corners alone
      found = i;
    }
  }
  return found;
}

// The cycle read from position `start` for `count` entries.
std::vector<int> read(const std::vector<int>& cycle, int start, int count) {
  std::vector<int> out;
  out.reserve(static_cast<size_t>(std::max(count, 0)));
  const int k = static_cast<int>(cycle.size());
  for (int t = 0; t < count; ++t) out.push_back(cycle[static_cast<size_t>((start + t) % k)]);
  return out;
}

// The border's wall at boundary vertex v (see NodeGroup::wall), if it is well defined.
bool border_wall(const TriMesh& mesh, const MeshTopology& topology, const std::vector<Vec3>& positions, int v,
                 Plane& wall) {
  bool on_boundary = false;
  const std::vector<int> fan = vertex_fan(mesh, topology, v, on_boundary);
  if (!on_boundary || fan.empty()) return false;
  const auto local = [&](int f) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
  };
  const Triangle& first = mesh.triangles[static_cast<size_t>(fan.front())];
  const Triangle& last = mesh.triangles[static_cast<size_t>(fan.back())];
  const int next = first[static_cast<size_t>((local(fan.front()) + 1) % 3)];
  const int prev = last[static_cast<size_t>((local(fan.back()) + 2) % 3)];
  Vec3 normal = Vec3::Zero();
  for (int f : fan) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    const Vec3& a = positions[static_cast<size_t>(t[0])];
    normal += (positions[static_cast<size_t>(t[1])] - a).cross(positions[static_cast<size_t>(t[2])] - a);
  }
  const Vec3 along = positions[static_cast<size_t>(next)] - positions[static_cast<size_t>(prev)];
  const Vec3 n = along.cross(normal);
  if (!(n.norm() > 1e-12 * along.norm() * normal.norm()) || !n.allFinite()) return false;
  wall = Plane::through(positions[static_cast<size_t>(v)], n.normalized());
  return true;
}

}  // namespace

NodeGroups group_corners(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                         const PanelGraph& graph, const std::vector<Vec3>& positions, const std::vector<int>& master_of,
                         double max_chain_length, const std::vector<std::pair<int, int>>& forced,
                         const HeldGrouping& held) {
  const auto tail = [&](int h) { return mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>(h % 3)]; };
  const auto head = [&](int h) {
    return mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)];
  };
  // Short chains between two clusters, each once (seen from the cluster with the smaller id).
  std::vector<Chain> chains;
  for (size_t c = 0; c < graph.loops.size(); ++c) {
    const std::vector<int>& loop = graph.loops[c];
    if (loop.empty() || graph.corner_of_vertex[static_cast<size_t>(tail(loop.front()))] < 0) continue;
    int start = graph.corner_of_vertex[static_cast<size_t>(tail(loop.front()))];
    double length = 0.0;
    for (int h : loop) {
      length += (positions[static_cast<size_t>(head(h))] - positions[static_cast<size_t>(tail(h))]).norm();
      const int corner = graph.corner_of_vertex[static_cast<size_t>(head(h))];
      if (corner < 0) continue;
      const int other = PanelGraph::other_side(topology, labels, h);
      const int pv = graph.corners[static_cast<size_t>(start)].vertex;
      const int qv = graph.corners[static_cast<size_t>(corner)].vertex;
      const bool together = std::binary_search(held.together.begin(), held.together.end(),
                                               std::make_pair(std::min(pv, qv), std::max(pv, qv)));
      const bool apart = !together && (std::binary_search(held.apart.begin(), held.apart.end(), pv) ||
                                       std::binary_search(held.apart.begin(), held.apart.end(), qv));
      const bool force =
          together || std::find(forced.begin(), forced.end(),
                                std::make_pair(std::min(start, corner), std::max(start, corner))) != forced.end();
      if (other != kBoundary && static_cast<int>(c) < other && (length <= max_chain_length || force) && !apart &&
          corner != start)
        chains.push_back({force ? -1.0 : length, start, corner, static_cast<int>(c), other});
      start = corner;
      length = 0.0;
    }
  }
  std::sort(chains.begin(), chains.end());

  NodeGroups out;
  out.group_of_corner.assign(graph.corners.size(), -1);
  out.groups.reserve(graph.corners.size());  // at most one group per corner
  for (const Chain& ch : chains) {
    if (out.group_of_corner[static_cast<size_t>(ch.from)] >= 0 || out.group_of_corner[static_cast<size_t>(ch.to)] >= 0)
      continue;
    const Corner& p = graph.corners[static_cast<size_t>(ch.from)];
    const Corner& q = graph.corners[static_cast<size_t>(ch.to)];
    if (p.on_boundary && q.on_boundary) continue;
    const int kp = static_cast<int>(p.clusters.size()), kq = static_cast<int>(q.clusters.size());
    if (kp + kq - 2 > 7) continue;
    // At one end the two clusters read (u, v) counter-clockwise, at the other (v, u).
    int i = find_pair(p.clusters, ch.a, ch.b);
    int u = ch.a, v = ch.b;
    if (i < 0) i = find_pair(p.clusters, ch.b, ch.a), u = ch.b, v = ch.a;
    const int j = find_pair(q.clusters, v, u);
    if (i < 0 || j < 0) continue;
    // p from v round to u, then q strictly between u and v: the contracted chain's k-gon.
    NodeGroup g;
    g.clusters = read(p.clusters, i + 1, kp);
    const std::vector<int> rest = read(q.clusters, j + 1, kq);
    g.clusters.insert(g.clusters.end(), rest.begin() + 1, rest.end() - 1);
    std::vector<int> masters;
    for (int c : g.clusters) masters.push_back(c == kBoundary ? -1 : master_of[static_cast<size_t>(c)]);
    std::sort(masters.begin(), masters.end());
    if (std::adjacent_find(masters.begin(), masters.end()) != masters.end()) continue;
    g.corners = {ch.from, ch.to};
    g.reference = 0.5 * (positions[static_cast<size_t>(p.vertex)] + positions[static_cast<size_t>(q.vertex)]);
    g.on_boundary = p.on_boundary || q.on_boundary;
    out.group_of_corner[static_cast<size_t>(ch.from)] = out.group_of_corner[static_cast<size_t>(ch.to)] =
        static_cast<int>(out.groups.size());
    const Corner& edge = p.on_boundary ? p : q;
    if (g.on_boundary) g.has_wall = border_wall(mesh, topology, positions, edge.vertex, g.wall);
    out.groups.push_back(std::move(g));
  }
  for (size_t k = 0; k < graph.corners.size(); ++k) {
    if (out.group_of_corner[k] >= 0) continue;
    const Corner& c = graph.corners[k];
    out.group_of_corner[k] = static_cast<int>(out.groups.size());
    NodeGroup g{c.clusters, {static_cast<int>(k)}, positions[static_cast<size_t>(c.vertex)], c.on_boundary, false, {}};
    if (c.on_boundary) g.has_wall = border_wall(mesh, topology, positions, c.vertex, g.wall);
    out.groups.push_back(std::move(g));
  }
  return out;
}

}  // namespace ff
