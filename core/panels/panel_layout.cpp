#include "core/panels/panel_layout.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/panels/border_vertices.h"
#include "core/panels/glass_split.h"
#include "core/panels/panel_check.h"
#include "core/panels/vertex_rule.h"

namespace ff {

namespace {

// Sine of the least angle at which a boundary node's line may cross the border's wall.
constexpr double kMinWallCrossing = 0.2;

int position_of(const std::vector<int>& cycle, int cluster) {
  for (size_t i = 0; i < cycle.size(); ++i) {
    if (cycle[i] == cluster) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

PanelLayout::PanelLayout(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                         const std::vector<Vec3>& positions, const PanelGraph& graph, MasterPlanes planes,
                         const LayoutOptions& options, const std::vector<std::pair<int, int>>& forced,
                         bool build_panels)
    : mesh_(mesh),
      topology_(topology),
      labels_(labels),
      positions_(positions),
      graph_(graph),
      planes_(std::move(planes)),
      options_(options),
      groups_(group_corners(mesh, topology, labels, graph, positions, planes_.master_of, options.spike_distance, forced,
                            options.held_grouping)) {
  const size_t groups = groups_.groups.size();
  const size_t clusters = graph_.problems.size();
  pairing_.resize(groups);
  held_group_.assign(groups, 0);
  single_.assign(groups, 0);
  single_point_.assign(groups, Vec3::Zero());
  node_offset_.assign(groups + 1, 0);
  for (size_t g = 0; g < groups; ++g) {
    node_offset_[g + 1] = node_offset_[g] + static_cast<int>(groups_.groups[g].clusters.size()) - 2;
  }
  const size_t nodes = static_cast<size_t>(node_offset_[groups]);
  node_point_.assign(nodes, Vec3::Zero());
  node_planes_.assign(nodes, 0);
  node_exact_.assign(nodes, 1);
  if (!options_.locked_spike_distance.empty()) node_limit_.assign(nodes, options_.spike_distance);
  node_group_.assign(nodes, -1);
  node_alias_.assign(nodes, -1);
  groups_of_cluster_.assign(clusters, {});
  std::vector<std::vector<Pairing>> pairings;  // per k, node_pairings(k) once
  for (size_t g = 0; g < groups; ++g) {
    const NodeGroup& group = groups_.groups[g];
    for (int c : group.clusters) {
      if (c != kBoundary) groups_of_cluster_[static_cast<size_t>(c)].push_back(static_cast<int>(g));
    }
    const int k = static_cast<int>(group.clusters.size());
    if (k == 3) {
      pairing_[g] = Pairing{{0, 1, 2}};
    } else {
      // The pairing whose nodes stay closest to where they belong (fig. 6); validation and
      // switch_pairings() correct it where it flips an edge.
      if (pairings.size() <= static_cast<size_t>(k)) pairings.resize(static_cast<size_t>(k) + 1);
      if (pairings[static_cast<size_t>(k)].empty()) pairings[static_cast<size_t>(k)] = node_pairings(k);
      std::vector<Pairing> held;  // a copy only where locked panels' nodes filter them
      if (!options_.held_nodes.empty()) {
        held = pairings[static_cast<size_t>(k)];
        held_group_[g] = hold_pairings(group.clusters, options_.held_nodes, held);
      }
      const std::vector<Pairing>& options = held_group_[g] ? held : pairings[static_cast<size_t>(k)];
      double best = std::numeric_limits<double>::infinity();
      Pairing chosen = options.front();  // even if every cost is infinite or NaN
      for (const Pairing& p : options) {
        pairing_[g] = p;
        place_group_nodes(static_cast<int>(g));
        const double cost = pairing_cost(static_cast<int>(g));
        if (cost < best) best = cost, chosen = p;
      }
      pairing_[g] = chosen;
    }
    place_group_nodes(static_cast<int>(g));
    if (held_group_[g] && !options_.held_single.empty()) {
      // A group a lock holds as one point: its planes are held through it, so its nodes
      // coincide; one vertex, where the first is (make_group_single's aliasing).
      std::vector<int> clusters = clusters_of_group(static_cast<int>(g));
      std::sort(clusters.begin(), clusters.end());
      if (std::find(options_.held_single.begin(), options_.held_single.end(), clusters) != options_.held_single.end()) {
        single_[g] = 1;
        single_point_[g] = node_point_[static_cast<size_t>(node_offset_[g])];
        place_group_nodes(static_cast<int>(g));
      }
    }
  }
  on_short_loop_.assign(positions_.size(), 0);
  std::vector<int> loop_groups;
  for (const std::vector<int>& loop : topology_.boundary_loops) {
    loop_groups.clear();
    for (const int v : loop) {
      const int corner = graph_.corner_of_vertex[static_cast<size_t>(v)];
      if (corner < 0) continue;
      const int g = groups_.group_of_corner[static_cast<size_t>(corner)];
      if (std::find(loop_groups.begin(), loop_groups.end(), g) == loop_groups.end()) loop_groups.push_back(g);
      if (loop_groups.size() >= 3) break;
    }
    if (loop_groups.size() >= 3) continue;
    for (const int v : loop) on_short_loop_[static_cast<size_t>(v)] = 1;
  }
  faces_normal_.assign(clusters, Vec3::Zero());
  for (size_t f = 0; f < mesh_.triangles.size() && f < labels_.size(); ++f) {
    const Triangle& t = mesh_.triangles[f];
    const Vec3& a = positions_[static_cast<size_t>(t[0])];
    const size_t c = static_cast<size_t>(labels_[f]);
    if (c < clusters)
      faces_normal_[c] += (positions_[static_cast<size_t>(t[1])] - a).cross(positions_[static_cast<size_t>(t[2])] - a);
  }
  polygons_.resize(clusters);
  issues_.resize(clusters);
  built_ = build_panels;
  if (!built_) return;
  for (size_t c = 0; c < clusters; ++c) build_panel(static_cast<int>(c));
}

std::array<int, 3> PanelLayout::node_clusters(int node) const {
  const int g = node_group_[static_cast<size_t>(node)];
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  const NodeTriangle& tri = pairing_[static_cast<size_t>(g)][static_cast<size_t>(node - node_offset_[static_cast<size_t>(g)])];
  std::array<int, 3> out;
  for (int t = 0; t < 3; ++t) out[static_cast<size_t>(t)] = group.clusters[static_cast<size_t>(tri[static_cast<size_t>(t)])];
  std::sort(out.begin(), out.end());
  return out;
}

CornerNodes PanelLayout::corner_nodes(int cluster) const {
  CornerNodes out;
  std::vector<int> around;
  for (int g : groups_of_cluster_[static_cast<size_t>(cluster)]) {
    const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
    const int size = static_cast<int>(group.clusters.size());
    triangles_around(pairing_[static_cast<size_t>(g)], size, position_of(group.clusters, cluster), around);
    for (int t : around) out.nodes.push_back(node_clusters(node_offset_[static_cast<size_t>(g)] + t));
    std::vector<int> vertices;
    for (int k : group.corners) vertices.push_back(graph_.corners[static_cast<size_t>(k)].vertex);
    out.group_vertices.push_back(std::move(vertices));
    if (single_[static_cast<size_t>(g)]) {
      std::vector<int> clusters = clusters_of_group(g);
      std::sort(clusters.begin(), clusters.end());
      out.single_groups.push_back(std::move(clusters));
    }
  }
  return out;
}

int PanelLayout::num_invalid() const { return faults().invalid; }

PanelLayout::Faults PanelLayout::faults() const {
  Faults faults;
  for (const PanelIssues& i : issues_) {
    faults.invalid += i.valid() ? 0 : 1;
    faults.collapsed += i.collapsed ? 1 : 0;
  }
  return faults;
}

bool PanelLayout::touches_boundary(int g, int node) const {
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  const NodeTriangle& tri =
      pairing_[static_cast<size_t>(g)][static_cast<size_t>(node - node_offset_[static_cast<size_t>(g)])];
  for (int p : tri) {
    if (group.clusters[static_cast<size_t>(p)] == kBoundary) return true;
  }
  return false;
}

PanelLayout::NodeMasters PanelLayout::node_masters(size_t node) const {
  const int g = node_group_[node];
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  const NodeTriangle& tri =
      pairing_[static_cast<size_t>(g)][node - static_cast<size_t>(node_offset_[static_cast<size_t>(g)])];
  NodeMasters out;
  for (int p : tri) {
    const int c = group.clusters[static_cast<size_t>(p)];
    if (c == kBoundary) continue;
    const int m = planes_.master_of[static_cast<size_t>(c)];
    if (std::find(out.m, out.m + out.count, m) == out.m + out.count) out.m[out.count++] = m;
  }
  // Sorted by hand: three at most (std::sort here trips GCC's array-bounds warning).
  for (int i = 1; i < out.count; ++i) {
    for (int j = i; j > 0 && out.m[j - 1] > out.m[j]; --j) std::swap(out.m[j - 1], out.m[j]);
  }
  return out;
}

std::vector<int> PanelLayout::masters_of_node(size_t node) const {
  const NodeMasters m = node_masters(node);
  return std::vector<int>(m.m, m.m + m.count);
}

// Each node: the vertex rule on the distinct master planes of its triangle's clusters (the
// NULL cluster contributes none), nearest the group's reference point.
void PanelLayout::place_group_nodes(int g) {
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  const int first = node_offset_[static_cast<size_t>(g)];
  std::vector<NodeMasters>& masters = scratch_masters_;
  std::vector<Plane>& planes = scratch_planes_;
  masters.clear();
  for (int node = first; node < node_offset_[static_cast<size_t>(g) + 1]; ++node) {
    node_group_[static_cast<size_t>(node)] = g;
    masters.push_back(node_masters(static_cast<size_t>(node)));
    const auto same = std::find(masters.begin(), masters.end() - 1, masters.back());
    node_alias_[static_cast<size_t>(node)] = first + static_cast<int>(same - masters.begin());
    planes.clear();
    for (int i = 0; i < masters.back().count; ++i)
      planes.push_back(planes_.planes[static_cast<size_t>(masters.back().m[i])]);
    VertexRuleResult r = closest_point_on_planes(planes, group.reference);
    if (group.has_wall && planes.size() <= 2 && touches_boundary(g, node)) {
      // On the border's wall when the wall crosses the planes at a clear angle.
      std::vector<Plane> walled = planes;
      walled.push_back(group.wall);
      const Vec3 line = planes.size() == 2 ? planes[0].normal.cross(planes[1].normal).normalized() : Vec3::Zero();
      const double crossing =
          planes.size() == 2 ? std::abs(line.dot(group.wall.normal)) : planes[0].normal.cross(group.wall.normal).norm();
      if (crossing > kMinWallCrossing) {
        const VertexRuleResult w = closest_point_on_planes(walled, group.reference);
        if (w.exact) r = w;
      }
    }
    if (!node_limit_.empty()) {
      const NodeTriangle& tri =
          pairing_[static_cast<size_t>(g)][static_cast<size_t>(node - node_offset_[static_cast<size_t>(g)])];
      double limit = options_.spike_distance;
      for (int p : tri) {
        const int c = group.clusters[static_cast<size_t>(p)];
        if (c != kBoundary && static_cast<size_t>(c) < options_.locked_spike_distance.size())
          limit = std::max(limit, options_.locked_spike_distance[static_cast<size_t>(c)]);
      }
      node_limit_[static_cast<size_t>(node)] = limit;
    }
    node_point_[static_cast<size_t>(node)] = r.point;
    node_planes_[static_cast<size_t>(node)] = static_cast<int>(planes.size());
    node_exact_[static_cast<size_t>(node)] = r.exact ? 1 : 0;
    if (single_[static_cast<size_t>(g)]) {
      node_alias_[static_cast<size_t>(node)] = first;
      node_point_[static_cast<size_t>(node)] = single_point_[static_cast<size_t>(g)];
      std::vector<int> distinct;
      for (int c : clusters_of_group(g)) distinct.push_back(planes_.master_of[static_cast<size_t>(c)]);
      std::sort(distinct.begin(), distinct.end());
      node_planes_[static_cast<size_t>(node)] =
          static_cast<int>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
      node_exact_[static_cast<size_t>(node)] = 1;
    }
  }
}

// Distance of the group's nodes from their reference; planes without a common point, and two
// nodes on the same planes (the same point: a zero-length edge), cost as much as a far spike.
double PanelLayout::pairing_cost(int g) const {
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  const double penalty = 1e3 * options_.diameter;
  double cost = 0.0;
  std::vector<NodeMasters> seen;
  seen.reserve(static_cast<size_t>(node_offset_[static_cast<size_t>(g) + 1] - node_offset_[static_cast<size_t>(g)]));
  for (int node = node_offset_[static_cast<size_t>(g)]; node < node_offset_[static_cast<size_t>(g) + 1]; ++node) {
    cost += (node_point_[static_cast<size_t>(node)] - group.reference).norm();
    if (!node_exact_[static_cast<size_t>(node)]) cost += penalty;
    const NodeMasters masters = node_masters(static_cast<size_t>(node));
    if (std::find(seen.begin(), seen.end(), masters) != seen.end()) cost += penalty;
    seen.push_back(masters);
  }
  return cost;
}

std::vector<int> PanelLayout::clusters_of_group(int g) const {
  std::vector<int> out;
  out.reserve(groups_.groups[static_cast<size_t>(g)].clusters.size());
  for (int c : groups_.groups[static_cast<size_t>(g)].clusters) {
    if (c != kBoundary && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  }
  return out;
}

void PanelLayout::build_panel(int c) {
  PanelPolygon& poly = polygons_[static_cast<size_t>(c)];
  // Cleared, not replaced: a rebuild reuses the vectors' memory (layouts rebuild panels
  // many times per round).
  poly.points.clear(), poly.node.clear(), poly.corner.clear(), poly.reference.clear();
  PanelIssues& issues = issues_[static_cast<size_t>(c)];
  issues = PanelIssues{};
  const std::vector<int>& loop = graph_.loops[static_cast<size_t>(c)];
  if (graph_.problems[static_cast<size_t>(c)] != 0 || loop.empty()) {
    issues.not_disk = true;
    return;
  }
  const Plane& plane = planes_.plane_of(c);
  const auto head = [&](int h) {
    return mesh_.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)];
  };
  // The node groups along the loop, with the border vertices met before each: a range
  // [border, border_end) of `border` (the border vertices in loop order).
  using Event = ScratchEvent;
  std::vector<Event>& events = scratch_events_;
  std::vector<int>& border = scratch_border_;
  events.clear(), border.clear();
  int run_begin = 0;
  for (int h : loop) {
    const int v = head(h);
    const int corner = graph_.corner_of_vertex[static_cast<size_t>(v)];
    if (corner >= 0) {
      events.push_back(
          {groups_.group_of_corner[static_cast<size_t>(corner)], v, run_begin, static_cast<int>(border.size())});
      run_begin = static_cast<int>(border.size());
    } else if (PanelGraph::other_side(topology_, labels_, h) == kBoundary) {
      border.push_back(v);
    }
  }
  const int run_end = static_cast<int>(border.size());  // the vertices after the last corner
  // The two corners of a group meet the loop one after the other (the short chain between
  // them): the group's nodes come once.
  size_t kept = 0;
  for (size_t i = 0; i < events.size(); ++i) {
    const bool empty = events[i].border == events[i].border_end;
    if (i > 0 && events[i].group == events[kept - 1].group && empty) continue;
    events[kept++] = events[i];
  }
  events.resize(kept);
  if (events.size() > 1 && events.front().group == events.back().group &&
      events.front().border == events.front().border_end) {
    events.front().border = events.back().border;
    events.front().border_end = events.back().border_end;
    events.pop_back();
  }

  // Room for every vertex at once: a layout's first build of a panel would otherwise grow
  // four vectors step by step (a guess: two nodes per group, and the border vertices).
  const size_t room = 2 * events.size() + border.size();
  poly.points.reserve(room), poly.node.reserve(room), poly.corner.reserve(room), poly.reference.reserve(room);

  // Nodes, remembering where each border run goes.
  struct Run {
    size_t at;  // insert before polygon vertex `at`
    int begin, end;
  };
  std::vector<Run> runs;
  std::vector<int>& around = scratch_triangles_;
  for (const Event& e : events) {
    if (e.border != e.border_end) runs.push_back({poly.points.size(), e.border, e.border_end});
    const NodeGroup& group = groups_.groups[static_cast<size_t>(e.group)];
    const int i = position_of(group.clusters, c);
    const int size = static_cast<int>(group.clusters.size());
    triangles_around(pairing_[static_cast<size_t>(e.group)], size, i, around);
    for (int t : around) {
      const int node = node_alias_[static_cast<size_t>(node_offset_[static_cast<size_t>(e.group)] + t)];
      if (!poly.node.empty() && poly.node.back() == node) continue;  // one point, one vertex
      poly.points.push_back(node_point_[static_cast<size_t>(node)]);
      poly.node.push_back(node);
      poly.corner.push_back(e.vertex);
      poly.reference.push_back(group.reference);
    }
  }
  if (poly.node.size() > 1 && poly.node.front() == poly.node.back() && runs.empty()) {
    poly.points.pop_back(), poly.node.pop_back(), poly.corner.pop_back(), poly.reference.pop_back();
  }
  if (run_end > run_begin) runs.push_back({poly.points.size(), run_begin, run_end});  // a loop with no corner
  // Border vertices, last run first so earlier insert positions stay valid.
  const size_t fixed = poly.points.size();
  const bool locked = static_cast<size_t>(c) < options_.locked_diameter.size() &&
                      options_.locked_diameter[static_cast<size_t>(c)] > 0.0;
  const double tolerance =
      options_.border_tolerance * (locked ? options_.locked_diameter[static_cast<size_t>(c)] : options_.diameter);
  for (auto it = runs.rbegin(); it != runs.rend(); ++it) {
    const size_t at = it->at;
    std::vector<Vec3> projected;
    for (int j = it->begin; j < it->end; ++j)
      projected.push_back(plane.project(positions_[static_cast<size_t>(border[static_cast<size_t>(j)])]));
    const std::vector<int> keep =
        fixed == 0 ? thin_closed_border(projected, tolerance)
                   : thin_border(poly.points[(at + fixed - 1) % fixed], projected, poly.points[at % fixed], tolerance,
                                 fixed + runs.size() < 3 || on_short_loop_[static_cast<size_t>(
                                                                border[static_cast<size_t>(it->begin)])]
                                     ? 1
                                     : 0);
    std::vector<Vec3> points, references;
    std::vector<int> corners;
    for (int j : keep) {
      points.push_back(projected[static_cast<size_t>(j)]);
      corners.push_back(border[static_cast<size_t>(it->begin + j)]);
      references.push_back(positions_[static_cast<size_t>(corners.back())]);
    }
    const long where = static_cast<long>(at);
    poly.points.insert(poly.points.begin() + where, points.begin(), points.end());
    poly.node.insert(poly.node.begin() + where, points.size(), -1);
    poly.corner.insert(poly.corner.begin() + where, corners.begin(), corners.end());
    poly.reference.insert(poly.reference.begin() + where, references.begin(), references.end());
  }
  int inexact = 0;
  for (int node : poly.node) inexact += node >= 0 && !node_exact_[static_cast<size_t>(node)] ? 1 : 0;
  issues = check_panel(poly.points, poly.reference, plane, options_.spike_distance, options_.tolerance,
                       options_.min_corner_angle_deg, options_.glass);
  const Vec3& faces = faces_normal_[static_cast<size_t>(c)];
  if (judge_orientation_ && faces.squaredNorm() > 0.0 && !(plane.normal.dot(faces) > 0.0))
    issues.flipped = true;  // misoriented
  if (!node_limit_.empty()) {  // vertices of locked panels have their own limit
    issues.spike_vertices = 0;
    for (size_t i = 0; i < poly.points.size(); ++i)
      issues.spike_vertices += (poly.points[i] - poly.reference[i]).norm() <= spike_limit(poly, i, c) ? 0 : 1;
  }
  issues.spike_vertices = std::max(issues.spike_vertices, inexact);
  // Coverage: judged on panels that pass the paper's checks (the others are invalid anyway,
  // and a flipped panel's signed area says nothing).
  if (issues.valid() && faces.squaredNorm() > 0.0) {
    const Vec3& origin = poly.points.front();  // relative to a vertex: no cancellation far out
    Vec3 twice_area = Vec3::Zero();
    for (size_t i = 1; i + 1 < poly.points.size(); ++i)
      twice_area += (poly.points[i] - origin).cross(poly.points[i + 1] - origin);
    issues.collapsed = is_collapsed(plane.normal.dot(twice_area), plane.normal.dot(faces));
  }
}

double PanelLayout::spike_limit(const PanelPolygon& poly, size_t i, int cluster) const {
  if (node_limit_.empty()) return options_.spike_distance;
  const int node = poly.node[i];
  if (node >= 0) return node_limit_[static_cast<size_t>(node)];
  const std::vector<double>& locked = options_.locked_spike_distance;
  return static_cast<size_t>(cluster) < locked.size() ? std::max(options_.spike_distance, locked[static_cast<size_t>(cluster)])
                                                      : options_.spike_distance;
}

void PanelLayout::rebuild(const std::vector<int>& clusters) {
  for (int c : clusters) build_panel(c);
}

void PanelLayout::rebuild_all() {
  for (size_t g = 0; g < groups_.groups.size(); ++g) place_group_nodes(static_cast<int>(g));
  for (size_t c = 0; c < polygons_.size(); ++c) build_panel(static_cast<int>(c));
}

std::vector<int> PanelLayout::problem_corners(int c) const {
  const PanelPolygon& poly = polygons_[static_cast<size_t>(c)];
  const PanelIssues& issues = issues_[static_cast<size_t>(c)];
  std::vector<int> out;
  for (size_t i = 0; i < poly.points.size(); ++i) {
    const bool spike = !((poly.points[i] - poly.reference[i]).norm() <= spike_limit(poly, i, c));
    if (spike || issues.flipped || issues.not_star || issues.not_simple) out.push_back(poly.corner[i]);
  }
  // An acute corner only (the panel otherwise fine): split next to that corner.
  if (out.empty() && issues.acute_corner) {
    const Plane& plane = planes_.plane_of(c);
    const PlaneFrame frame = make_plane_frame(plane.offset * plane.normal, plane.normal);
    std::vector<Vec2> polygon;
    for (const Vec3& p : poly.points) polygon.push_back(frame.to_2d(p));
    for (int i : acute_corners_after_split(polygon, options_.min_corner_angle_deg, options_.glass))
      out.push_back(poly.corner[static_cast<size_t>(i)]);
  }
  return out;
}

void PanelLayout::judge_orientation() {
  if (judge_orientation_) return;
  judge_orientation_ = true;
  for (size_t c = 0; c < polygons_.size(); ++c) build_panel(static_cast<int>(c));
}

void PanelLayout::judge_min_corner_angle(double deg) {
  if (options_.min_corner_angle_deg == deg) return;
  options_.min_corner_angle_deg = deg;
  for (size_t c = 0; c < polygons_.size(); ++c) build_panel(static_cast<int>(c));
}

void PanelLayout::set_planes(std::vector<Plane> planes) {
  std::vector<Plane> old = std::move(planes_.planes);
  planes_.planes = std::move(planes);
  rebuild_changed(old, !built_);
  built_ = true;
}

}  // namespace ff
