#include "core/quality/report.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <tuple>

#include "core/panels/panel_check.h"
#include "core/panels/panel_crossings.h"
#include "core/panels/polygon2d.h"
#include "core/quality/hausdorff.h"
#include "core/quality/planarity.h"
#include "core/util/error.h"

namespace ff {

namespace {

void check_size(size_t size, size_t expected, const char* what, const char* per) {
  if (size != 0 && size != expected) {
    throw InputError(std::string("quality: ") + what + " has " + std::to_string(size) + " entries for " +
                     std::to_string(expected) + " " + per);
  }
}

struct PanelTopology {
  int used_vertices = 0;
  int euler = 0;
  int boundary_loops = 0;
  bool oriented_manifold = true;
  std::map<int, int> interior_valence;
};

// Whether the corners around one vertex (each: the vertex before it and after it in its
// panel) chain into one cycle (disk) or one path (half-disk). Corner c continues to corner
// d when d comes in from where c goes out (the panel across the edge v -> c.out).
bool single_fan(std::vector<std::pair<int, int>> in_out) {
  const size_t n = in_out.size();
  std::sort(in_out.begin(), in_out.end());
  const auto find_in = [&](int in) -> int {
    const auto it = std::lower_bound(in_out.begin(), in_out.end(), std::make_pair(in, -1));
    return it != in_out.end() && it->first == in ? static_cast<int>(it - in_out.begin()) : -1;
  };
  std::vector<int> outs(n);
  for (size_t i = 0; i < n; ++i) outs[i] = in_out[i].second;
  std::sort(outs.begin(), outs.end());
  if (std::adjacent_find(outs.begin(), outs.end()) != outs.end()) return false;
  for (size_t i = 1; i < n; ++i) {
    if (in_out[i].first == in_out[i - 1].first) return false;
  }
  int start = 0, starts = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!std::binary_search(outs.begin(), outs.end(), in_out[i].first)) {
      start = static_cast<int>(i);
      ++starts;
    }
  }
  if (starts > 1) return false;
  size_t visited = 0;
  int c = start;
  do {
    ++visited;
    c = find_in(in_out[static_cast<size_t>(c)].second);
  } while (c >= 0 && c != start && visited <= n);
  return visited == n && (starts == 1 ? c < 0 : c == start);
}

PanelTopology panel_topology(const PanelMesh& panels) {
  PanelTopology out;
  struct HalfEdge {
    int lo, hi, from, panel;
  };
  std::vector<HalfEdge> half_edges;
  std::vector<std::tuple<int, int, int, int>> corners;  // vertex, panel, in, out
  for (int p = 0; p < panels.num_panels(); ++p) {
    const std::vector<int>& poly = panels.panels[static_cast<size_t>(p)];
    const size_t k = poly.size();
    std::vector<int> sorted = poly;  // a repeated vertex pinches the panel
    std::sort(sorted.begin(), sorted.end());
    if (k < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) out.oriented_manifold = false;
    for (size_t i = 0; i < k; ++i) {
      const int a = poly[i], b = poly[(i + 1) % k];
      corners.emplace_back(a, p, poly[(i + k - 1) % k], b);
      if (a != b) half_edges.push_back({std::min(a, b), std::max(a, b), a, p});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& l, const HalfEdge& r) {
    return std::tie(l.lo, l.hi, l.panel, l.from) < std::tie(r.lo, r.hi, r.panel, r.from);
  });
  std::vector<std::pair<int, int>> boundary;  // directed boundary half-edges (from, to)
  int edges = 0;
  for (size_t i = 0; i < half_edges.size();) {
    size_t j = i;
    while (j < half_edges.size() && half_edges[j].lo == half_edges[i].lo && half_edges[j].hi == half_edges[i].hi) ++j;
    ++edges;
    if (j - i == 1) {
      const HalfEdge& h = half_edges[i];
      boundary.emplace_back(h.from, h.from == h.lo ? h.hi : h.lo);
    } else if (j - i > 2 || half_edges[i].from == half_edges[i + 1].from) {
      out.oriented_manifold = false;
    }
    i = j;
  }

  std::vector<int> boundary_vertices;
  for (const auto& [a, b] : boundary) {
    boundary_vertices.push_back(a);
    boundary_vertices.push_back(b);
  }
  std::sort(boundary_vertices.begin(), boundary_vertices.end());
  std::sort(corners.begin(), corners.end());
  int faces = 0;
  for (const auto& poly : panels.panels) faces += poly.empty() ? 0 : 1;
  for (size_t i = 0; i < corners.size();) {
    const int v = std::get<0>(corners[i]);
    size_t j = i;
    int distinct_panels = 0;
    std::vector<std::pair<int, int>> in_out;
    for (; j < corners.size() && std::get<0>(corners[j]) == v; ++j) {
      if (j == i || std::get<1>(corners[j]) != std::get<1>(corners[j - 1])) ++distinct_panels;
      in_out.emplace_back(std::get<2>(corners[j]), std::get<3>(corners[j]));
    }
    ++out.used_vertices;
    if (out.oriented_manifold && !single_fan(std::move(in_out))) out.oriented_manifold = false;
    if (!std::binary_search(boundary_vertices.begin(), boundary_vertices.end(), v)) {
      ++out.interior_valence[distinct_panels];
    }
    i = j;
  }
  out.euler = out.used_vertices - edges + faces;

  // Loops: walk boundary half-edges head to tail until back at the start vertex (exact on
  // an oriented manifold; at a pinched vertex this closes the smaller loop first).
  std::sort(boundary.begin(), boundary.end());
  std::vector<char> visited(boundary.size(), 0);
  for (size_t start = 0; start < boundary.size(); ++start) {
    if (visited[start]) continue;
    ++out.boundary_loops;
    size_t cur = start;
    for (;;) {
      visited[cur] = 1;
      const int head = boundary[cur].second;
      if (head == boundary[start].first) break;
      auto it = std::lower_bound(boundary.begin(), boundary.end(), std::make_pair(head, INT_MIN));
      while (it != boundary.end() && it->first == head && visited[static_cast<size_t>(it - boundary.begin())]) ++it;
      if (it == boundary.end() || it->first != head) break;
      cur = static_cast<size_t>(it - boundary.begin());
    }
  }
  return out;
}

}  // namespace

QualityReport measure_quality(const TriMesh& input, const MeshTopology& input_topology, const PanelMesh& panels,
                              const QualityOptions& options) {
  const size_t np = panels.panels.size(), nv = panels.vertices.size();
  check_size(panels.plane_normals.size(), np, "plane_normals", "panels");
  check_size(panels.issues.size(), np, "issues", "panels");
  check_size(panels.vertex_corner.size(), nv, "vertex_corner", "panel vertices");
  check_size(panels.face_panel.size(), static_cast<size_t>(input.num_faces()), "face_panel", "input faces");
  if (!(options.spike_factor > 0.0) || !(options.tolerance >= 0.0)) {
    throw InputError("quality: spike_factor must be positive and tolerance not negative");
  }

  for (size_t p = 0; p < np; ++p) {
    for (int v : panels.panels[p]) {
      if (v < 0 || static_cast<size_t>(v) >= nv) {
        throw InputError("quality: panel " + std::to_string(p) + " refers to vertex " + std::to_string(v) + " of " +
                         std::to_string(nv));
      }
      if (!panels.vertices[static_cast<size_t>(v)].allFinite()) {
        throw InputError("quality: panel vertex " + std::to_string(v) + " is not finite");
      }
    }
  }

  QualityReport r;
  r.panels = panels.num_panels();
  const HausdorffResult h = hausdorff_distance(input, panels, options.samples_per_side);  // validates input
  r.hausdorff = h.two_sided;
  r.hausdorff_input_to_panels = h.input_to_panels;
  r.hausdorff_panels_to_input = h.panels_to_input;
  r.hausdorff_worst_point = h.worst_point;

  PanelTopology topo = panel_topology(panels);
  r.vertices = topo.used_vertices;
  r.euler_in = euler_characteristic(input, input_topology);
  r.euler_out = topo.euler;
  r.boundary_loops_in = static_cast<int>(input_topology.boundary_loops.size());
  r.boundary_loops_out = topo.boundary_loops;
  r.oriented_manifold = topo.oriented_manifold;
  r.topology_preserved =
      r.oriented_manifold && r.euler_in == r.euler_out && r.boundary_loops_in == r.boundary_loops_out;
  r.interior_valence = std::move(topo.interior_valence);
  int interior = 0;
  for (const auto& [valence, count] : r.interior_valence) interior += count;
  const auto three = r.interior_valence.find(3);
  const int valence3 = three == r.interior_valence.end() ? 0 : three->second;
  r.valence3_share = interior > 0 ? static_cast<double>(valence3) / interior : 1.0;

  // Spikes, per used vertex: D is the expected panel diameter.
  std::vector<char> spike(nv, 0);
  if (!panels.vertex_corner.empty() && np > 0) {
    const double d = std::sqrt(total_area(input) / static_cast<double>(np));
    std::vector<char> used(nv, 0);
    for (const auto& poly : panels.panels) {
      for (int v : poly) {
        if (v >= 0 && static_cast<size_t>(v) < nv) used[static_cast<size_t>(v)] = 1;
      }
    }
    for (size_t v = 0; v < nv; ++v) {
      const int corner = panels.vertex_corner[v];
      if (!used[v] || corner < 0) continue;
      if (corner >= input.num_vertices()) {
        throw InputError("quality: panel vertex " + std::to_string(v) + " has corner " + std::to_string(corner) +
                         " of " + std::to_string(input.num_vertices()));
      }
      // The producer's own reference and distance when it gives them (the panel phase
      // measures the average cluster diameter, paper 2.3), else the corner and factor * D.
      const bool own = panels.vertex_reference.size() == nv && panels.spike_distance > 0.0;
      const Vec3& where = own ? panels.vertex_reference[v] : input.positions[static_cast<size_t>(corner)];
      const double limit = !own                                       ? options.spike_factor * d
                           : panels.vertex_spike_distance.size() == nv ? panels.vertex_spike_distance[v]
                                                                       : panels.spike_distance;
      spike[v] = (panels.vertices[v] - where).norm() > limit;
      r.spike_vertices += spike[v];
      if (spike[v]) r.spike_vertex_ids.push_back(static_cast<int>(v));
    }
  }

  // Orientation against the input faces of each panel (area-weighted normal sum).
  std::vector<Vec3> face_normal_sum(np, Vec3::Zero());
  if (!panels.face_panel.empty()) {
    for (int f = 0; f < input.num_faces(); ++f) {
      const int p = panels.face_panel[static_cast<size_t>(f)];
      if (p < 0) continue;
      if (static_cast<size_t>(p) >= np) throw InputError("quality: face_panel names a missing panel");
      face_normal_sum[static_cast<size_t>(p)] += face_normal(input, f) * face_area(input, f);
    }
    r.misoriented_panels = 0;
  }
  // Glass pieces (panel_source) are judged as the panel they were cut from, on all of its
  // faces: the pieces share its plane, and the faces under one piece alone can face away on a
  // sharply curved part (cow.off in glass mode: a sliver piece on a leg) although the panel
  // as a whole faces its faces, as the panel phase judged it before the cut. Coverage below
  // too: a piece adds its area to the panel it was cut from.
  const bool pieces = !panels.face_panel.empty() && panels.panel_source.size() == np;
  const auto source_of = [&](size_t p) { return pieces ? static_cast<size_t>(panels.panel_source[p]) : p; };
  if (pieces) {
    std::vector<Vec3> by_source(np, Vec3::Zero());
    for (size_t p = 0; p < np; ++p) {
      const int source = panels.panel_source[p];
      if (source < 0 || static_cast<size_t>(source) >= np)
        throw InputError("quality: panel_source names a missing panel");
      by_source[static_cast<size_t>(source)] += face_normal_sum[p];
    }
    for (size_t p = 0; p < np; ++p) face_normal_sum[p] = by_source[source_of(p)];
  }

  // Coverage, per source panel (sources validated above; coverage needs the faces too).
  std::vector<double> covered(np, 0.0), faces_projected(np, 0.0);
  std::vector<int> first_piece(np, -1);
  std::vector<char> source_invalid(np, 0);  // judged only on valid panels, as the layout judges it

  const double tol = options.tolerance * bbox_diagonal(input);
  double min_angle = np > 0 ? 360.0 : 0.0;
  for (int p = 0; p < r.panels; ++p) {
    const std::vector<int>& poly = panels.panels[static_cast<size_t>(p)];
    const PlaneFrame frame = panel_frame(panels, p);  // validates the indices
    const std::vector<Vec2> poly2d = panel_polygon_2d(panels, p, frame);
    std::vector<Vec3> points;
    for (int v : poly) points.push_back(panels.vertices[static_cast<size_t>(v)]);
    const double planarity = polygon_planarity(points);
    if (r.max_planarity_panel < 0 || planarity > r.max_planarity) {
      r.max_planarity = planarity;
      r.max_planarity_panel = p;
    }
    const double floor = planarity_rounding_floor(points);
    const double floor_solve = planarity_rounding_floor(points, panels.solve_origin);
    r.planarity_floor = std::max(r.planarity_floor, floor);
    r.planarity_floor_solve = std::max(r.planarity_floor_solve, floor_solve);
    // Checked here, not taken from the panel phase: a panel off its plane is no part to cut,
    // whatever the flags say (a flag error would otherwise pass with only a warning).
    const bool off_plane = off_its_plane(planarity, floor, floor_solve);
    r.off_plane_panels += off_plane;
    const bool bent = options.flat_panels && off_plane;

    const bool simple = is_simple(poly2d, tol);
    const std::vector<Vec2> kernel = polygon_kernel(poly2d, tol);
    const Vec2 reference = kernel.empty() ? vertex_average(poly2d) : polygon_centroid(kernel);
    const std::vector<int> flipped_starts = flipped_edges(poly2d, reference);
    const int flipped = static_cast<int>(flipped_starts.size());
    for (const int i : flipped_starts)
      r.flipped_edge_vertices.push_back(
          {poly[static_cast<size_t>(i)], poly[(static_cast<size_t>(i) + 1) % poly.size()]});
    const PolygonCorner sharpest = smallest_interior_angle(poly2d);
    if (sharpest.angle_deg < min_angle) {  // (a panel of fewer than 3 vertices: 0, at its first)
      min_angle = sharpest.angle_deg;
      r.min_corner_angle_panel = p;
      const size_t at = static_cast<size_t>(std::max(sharpest.index, 0));
      if (at < poly.size()) r.min_corner_angle_point = panels.vertices[static_cast<size_t>(poly[at])];
    }
    // Glass: judged on the counter-clockwise outline (a clockwise one is flipped anyway).
    const bool concave = signed_area(poly2d) > 0.0 && !reflex_corners(poly2d).empty();
    int acute = 0;
    if (options.min_corner_angle_deg > 0.0) {
      const std::vector<int> corners = acute_corners(poly2d, options.min_corner_angle_deg);
      acute = static_cast<int>(corners.size());
      for (const int i : corners) r.acute_corner_vertex_ids.push_back(poly[static_cast<size_t>(i)]);
    }
    r.concave_panels += concave;
    r.acute_corners += acute;
    const size_t source = source_of(static_cast<size_t>(p));
    covered[source] += signed_area(poly2d);
    faces_projected[source] = frame.normal.dot(face_normal_sum[static_cast<size_t>(p)]);
    if (first_piece[source] < 0) first_piece[source] = p;

    bool has_spike = false;
    for (int v : poly) has_spike = has_spike || spike[static_cast<size_t>(v)];
    bool misoriented = false;
    const Vec3& faces_normal = face_normal_sum[static_cast<size_t>(p)];
    if (!panels.face_panel.empty() && faces_normal.squaredNorm() > 0.0) {
      misoriented = newell_normal(points).dot(faces_normal) <= 0.0;
      r.misoriented_panels += misoriented;
    }

    r.non_simple_panels += !simple;
    r.non_star_panels += kernel.empty();
    r.flipped_edges += flipped;
    const bool producer_invalid = !panels.issues.empty() && !panels.issues[static_cast<size_t>(p)].valid();
    const bool glass_invalid = (options.glass && concave) || acute > 0;
    const bool otherwise_invalid =
        producer_invalid || !simple || kernel.empty() || flipped > 0 || has_spike || misoriented || glass_invalid;
    if (bent && !otherwise_invalid) r.solver_error_panel_ids.push_back(p);
    if (otherwise_invalid || bent) {
      r.invalid_panel_ids.push_back(p);
      source_invalid[source_of(static_cast<size_t>(p))] = 1;
    }
  }
  // Panels that pass through each other (the indices were checked in the loop above):
  // reported, not yet counted invalid (report.h).
  if (panels.plane_normals.size() == np) {
    std::vector<double> offsets = panels.plane_offsets;
    if (offsets.size() != np) {  // planes given by their normals only: through the first vertex
      offsets.assign(np, 0.0);
      for (size_t p = 0; p < np; ++p) {
        if (!panels.panels[p].empty() && panels.panels[p][0] >= 0 &&
            static_cast<size_t>(panels.panels[p][0]) < panels.vertices.size())
          offsets[p] = panels.plane_normals[p].dot(panels.vertices[static_cast<size_t>(panels.panels[p][0])]);
      }
    }
    for (const PanelCrossing& c : panel_crossings(panels.vertices, panels.panels, panels.plane_normals, offsets)) {
      r.crossing_pairs.push_back({c.a, c.b});
      r.crossing_points.push_back(c.point);
      r.max_crossing_depth = std::max(r.max_crossing_depth, c.depth_share);
    }
  }
  {
    const SurfaceCrossings own = options.input_crossings ? *options.input_crossings : surface_crossings(input);
    r.input_crossings = own.count();
    r.input_crossing_point = own.first_point();
    r.input_crossing_places = own.checked ? own.places : 0;
  }
  // A cluster that could not become a panel leaves its faces uncovered: it counts as an
  // invalid panel too, so the count never hides it (write_invalid_panels lists it).
  r.invalid_panels = static_cast<int>(r.invalid_panel_ids.size() + panels.unbuilt_clusters.size());
  if (!panels.face_panel.empty()) {
    std::vector<char> collapsed(np, 0);
    for (size_t q = 0; q < np; ++q) {
      if (first_piece[q] < 0 || source_invalid[q] || !(faces_projected[q] > 0.0)) continue;
      const double coverage = covered[q] / faces_projected[q];
      collapsed[q] = is_collapsed(covered[q], faces_projected[q]);
      if (r.min_panel_coverage_panel < 0 || coverage < r.min_panel_coverage)
        r.min_panel_coverage = coverage, r.min_panel_coverage_panel = first_piece[q];
    }
    for (size_t p = 0; p < np; ++p) r.collapsed_panels += collapsed[source_of(p)];  // each glass piece
    const size_t named = static_cast<size_t>(r.min_panel_coverage_panel);
    if (r.min_panel_coverage_panel >= 0 && named < panels.panel_cluster.size())
      r.min_panel_coverage_cluster = panels.panel_cluster[named];
  }
  r.min_corner_angle_deg = min_angle;
  r.min_corner_angle_target_deg = options.min_corner_angle_deg;
  return r;
}

}  // namespace ff
