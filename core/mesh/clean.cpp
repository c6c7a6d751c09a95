#include "core/mesh/clean.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "core/mesh/clean_local.h"
#include "core/mesh/fill_holes.h"
#include "core/mesh/half_edges.h"
#include "core/mesh/manifold_part.h"
#include "core/mesh/orient.h"
#include "core/mesh/part_spread.h"
#include "core/mesh/vertex_spread.h"
#include "core/mesh/weld.h"
#include "core/util/error.h"
#include "core/util/short_number.h"
#include "core/util/union_find.h"

namespace ff {

namespace {

using detail::HalfEdgeGroups;

void require_finite(const std::vector<Vec3>& positions) {
  for (size_t v = 0; v < positions.size(); ++v) {
    if (!positions[v].allFinite()) {
      throw InputError("vertex " + std::to_string(v) + " has a non-finite coordinate " +
                       detail::format_point(positions[v]));
    }
  }
}

// Areas, the sliver test and the metric's moments take squares and fourth powers of a model's
// size, which leave a double's range beyond about 1e+77; well inside that, 1e-30 to 1e+30
// across covers every real model in any unit. One outside was exported in a wrong unit or is
// damaged: said, instead of sliver tests that pass every face (or none) and a silent mess.
constexpr double kMinExtent = 1e-30, kMaxExtent = 1e30;

void require_workable_extent(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Triangle& t : triangles) {
    for (int v : t) {
      lo = lo.cwiseMin(positions[static_cast<size_t>(v)]);
      hi = hi.cwiseMax(positions[static_cast<size_t>(v)]);
    }
  }
  const double extent = 2.0 * (0.5 * hi - 0.5 * lo).maxCoeff();  // no overflow on the way
  if (extent == 0.0) throw InputError("the mesh has no extent: all its vertices coincide");
  if (extent >= kMinExtent && extent <= kMaxExtent) return;
  if (!(extent <= kMaxExtent)) {
    // Where one thing makes it so, it is named: a part far from the rest (which --largest-part
    // drops before this), or one corrupted coordinate in a part (3e38 from a broken binary
    // STL). On the vertices the faces use, numbered as in the input.
    std::vector<int> index(positions.size(), -1), source;
    TriMesh used;
    for (Triangle t : triangles) {
      for (int& v : t) {
        int& i = index[static_cast<size_t>(v)];
        if (i < 0) {
          i = used.num_vertices();
          used.positions.push_back(positions[static_cast<size_t>(v)]);
          source.push_back(v);
        }
        v = i;
      }
      used.triangles.push_back(t);
    }
    const std::vector<int> roots = vertex_part_roots(used);
    require_compact_parts(used, roots);
    require_no_stray_vertex(used, source, roots);
  }
  throw InputError("the mesh is " + short_number(extent) + " across, outside the 1e-30 to 1e+30 that can be measured " +
                   "in double precision: rescale it (was it exported in another unit?)");
}

struct FaceFilter {
  std::vector<int> kept;  // input faces that survive, in input order
  int degenerate = 0;
  int duplicate = 0;
};

// Drops faces with a repeated vertex, then every face whose vertex set (either
// orientation) already appeared in an earlier face. Sorted by smallest vertex with a
// counting sort, so O(m) plus tiny per-vertex sorts.
FaceFilter filter_faces(const std::vector<Triangle>& tris, int num_vertices) {
  FaceFilter result;
  const size_t m = tris.size(), n = static_cast<size_t>(num_vertices);
  std::vector<char> keep(m, 1);
  std::vector<int> start(n + 1, 0);
  for (size_t f = 0; f < m; ++f) {
    const Triangle& t = tris[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      keep[f] = 0;
      ++result.degenerate;
      continue;
    }
    ++start[static_cast<size_t>(*std::min_element(t.begin(), t.end())) + 1];
  }
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];

  // (middle << 32 | largest vertex, face) per face, bucketed by the smallest vertex.
  std::vector<std::pair<std::uint64_t, int>> keyed(static_cast<size_t>(start[n]));
  std::vector<int> cursor(start.begin(), start.end() - 1);
  for (size_t f = 0; f < m; ++f) {
    if (!keep[f]) continue;
    Triangle t = tris[f];
    std::sort(t.begin(), t.end());
    const std::uint64_t key = (static_cast<std::uint64_t>(t[1]) << 32) | static_cast<std::uint64_t>(t[2]);
    keyed[static_cast<size_t>(cursor[static_cast<size_t>(t[0])]++)] = {key, static_cast<int>(f)};
  }
  for (size_t v = 0; v < n; ++v) {
    const auto begin = keyed.begin() + start[v], end = keyed.begin() + start[v + 1];
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it) {
      if (it != begin && it->first == (it - 1)->first) {
        keep[static_cast<size_t>(it->second)] = 0;
        ++result.duplicate;
      }
    }
  }
  for (size_t f = 0; f < m; ++f) {
    if (keep[f]) result.kept.push_back(static_cast<int>(f));
  }
  return result;
}

// Collinear up to rounding: height below 1e-12 of the longest edge.
int count_zero_area(const std::vector<Triangle>& tris, const std::vector<Vec3>& positions) {
  int count = 0;
  for (const Triangle& t : tris) {
    const Vec3& a = positions[static_cast<size_t>(t[0])];
    const Vec3& b = positions[static_cast<size_t>(t[1])];
    const Vec3& c = positions[static_cast<size_t>(t[2])];
    const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() <= 1e-12 * longest2) ++count;
  }
  return count;
}

// Vertices that welding may merge: those on an edge not shared by exactly two faces, and
// unreferenced ones. A vertex whose edges are all stitched already gains nothing from
// welding, and merging it with a coincident one would glue two sheets that merely touch
// into a non-manifold edge (cow.off has one such spot).
std::vector<char> weldable_vertices(const std::vector<Triangle>& tris, int num_vertices) {
  std::vector<char> weldable(static_cast<size_t>(num_vertices), 1);
  for (const Triangle& t : tris) {
    for (int v : t) weldable[static_cast<size_t>(v)] = 0;
  }
  const HalfEdgeGroups groups = detail::group_half_edges(tris, num_vertices);
  for (int g = 0; g < groups.num_groups(); ++g) {
    if (groups.group_size(g) == 2) continue;
    const int h = groups.first(g);
    weldable[static_cast<size_t>(detail::tail_of(tris, h))] = 1;
    weldable[static_cast<size_t>(detail::head_of(tris, h))] = 1;
  }
  return weldable;
}

// Welds all vertices first; only when a weld involves a vertex that may be stitched
// already (used by two or more faces: never in soups) does it look for the stitched ones
// and, if a weld involves one, weld again without them.
std::vector<int> weld(const TriMesh& input, double tolerance) {
  std::vector<int> rep = detail::weld_representatives(input.positions, tolerance);
  const auto any_weld_touches = [&rep](const auto& is_marked) {
    for (size_t v = 0; v < rep.size(); ++v) {
      const auto r = static_cast<size_t>(rep[v]);
      if (r != v && (is_marked(v) || is_marked(r))) return true;
    }
    return false;
  };
  if (!any_weld_touches([](size_t) { return true; })) return rep;
  std::vector<int> faces_at(rep.size(), 0);
  for (const Triangle& t : input.triangles) {
    for (int v : t) ++faces_at[static_cast<size_t>(v)];
  }
  if (!any_weld_touches([&](size_t v) { return faces_at[v] > 1; })) return rep;
  const std::vector<char> weldable = weldable_vertices(input.triangles, static_cast<int>(rep.size()));
  if (!any_weld_touches([&](size_t v) { return !weldable[v]; })) return rep;
  return detail::weld_representatives(input.positions, tolerance, weldable);
}


// Gives each fan of faces around a vertex (faces joined through edges at that vertex) its
// own vertex: the fan with the lowest face keeps the original, the others get new
// vertices num_vertices + k, a copy of copy_origin[k]. Corner 3f+i of face f is unioned
// with the matching corner across each interior edge; a vertex with corners in several
// sets is non-manifold. Returns how many vertices were split. Edges keep their faces, so
// `groups` stays valid.
int split_nonmanifold_vertices(std::vector<Triangle>& tris, const HalfEdgeGroups& groups, int num_vertices,
                               std::vector<int>& copy_origin) {
  const size_t corners = 3 * tris.size();
  std::vector<int> parent(corners);
  std::iota(parent.begin(), parent.end(), 0);
  const auto unite = [&](int a, int b) {
    a = union_find_root(parent, a);
    b = union_find_root(parent, b);
    if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  };
  for (int g = 0; g < groups.num_groups(); ++g) {
    if (groups.group_size(g) != 2) continue;
    const int h1 = groups.first(g), h2 = groups.second(g);
    // Half-edge h starts at corner h; its head is the next corner of the face.
    if (detail::tail_of(tris, h1) == detail::tail_of(tris, h2)) {
      unite(h1, h2);
      unite(detail::next_in_face(h1), detail::next_in_face(h2));
    } else {
      unite(h1, detail::next_in_face(h2));
      unite(detail::next_in_face(h1), h2);
    }
  }

  std::vector<int> fan_vertex(corners, -1);
  std::vector<char> has_fan(static_cast<size_t>(num_vertices), 0);
  std::vector<char> was_split(static_cast<size_t>(num_vertices), 0);
  int split = 0;
  for (size_t c = 0; c < corners; ++c) {
    int& corner = tris[c / 3][c % 3];
    const size_t root = static_cast<size_t>(union_find_root(parent, static_cast<int>(c)));
    if (fan_vertex[root] < 0) {
      const auto v = static_cast<size_t>(corner);
      if (!has_fan[v]) {
        has_fan[v] = 1;
        fan_vertex[root] = corner;
      } else {
        fan_vertex[root] = num_vertices + static_cast<int>(copy_origin.size());
        copy_origin.push_back(corner);
        if (!was_split[v]) {
          was_split[v] = 1;
          ++split;
        }
      }
    }
    corner = fan_vertex[root];
  }
  return split;
}

// Non-manifold edges: refused with a NonManifoldError (naming the first edge and offering
// the largest manifold part), or with largest_manifold_part cut there and only the largest
// part kept (tris and kept, the input face of each, shrink to it); with that option a mesh of
// several parts keeps its largest as well. Returns, per vertex, whether it was used before
// the cut (empty when nothing was cut), so the vertices of the parts left out are not
// reported as unused ones; `outside` (per input face, of input_faces) marks the faces left
// out with their part.
std::vector<char> keep_manifold_part(std::vector<Triangle>& tris, std::vector<int>& kept,
                                     const std::vector<Vec3>& positions, const CleanOptions& options,
                                     CleanReport& report, size_t input_faces, std::vector<char>& outside) {
  const HalfEdgeGroups groups = detail::group_half_edges(tris, static_cast<int>(positions.size()));
  bool manifold = true;
  for (int g = 0; g < groups.num_groups() && manifold; ++g) manifold = groups.group_size(g) < 3;
  if (manifold && !options.largest_manifold_part) return {};
  const detail::ManifoldPart part = detail::largest_manifold_part(tris, positions);
  if (manifold && part.sheets <= 1) return {};  // one part: nothing to drop
  const int total = static_cast<int>(tris.size()), part_faces = static_cast<int>(part.faces.size());
  if (!options.largest_manifold_part) {
    try {
      detail::require_edge_manifold(groups, tris, positions);
    } catch (const InputError& e) {
      throw NonManifoldError(e.what(), part.nonmanifold_edges, part_faces, total);
    }
  }
  report.nonmanifold_edges_cut = part.nonmanifold_edges;
  report.faces_before_cut = total;
  report.faces_outside_part = total - part_faces;
  report.parts_dropped = part.sheets - 1;
  report.most_faces_dropped_part = part.most_faces_left_out;
  std::vector<Triangle> part_tris(part.faces.size());
  std::vector<int> part_kept(part.faces.size());
  for (size_t k = 0; k < part.faces.size(); ++k) {
    part_tris[k] = tris[static_cast<size_t>(part.faces[k])];
    part_kept[k] = kept[static_cast<size_t>(part.faces[k])];
  }
  std::vector<char> used(positions.size(), 0);
  for (const Triangle& t : tris) {
    for (int v : t) used[static_cast<size_t>(v)] = 1;
  }
  outside.assign(input_faces, 0);
  for (const int f : kept) outside[static_cast<size_t>(f)] = 1;
  for (const int f : part_kept) outside[static_cast<size_t>(f)] = 0;
  tris = std::move(part_tris);
  kept = std::move(part_kept);
  return used;
}

std::string count_of(int n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace

std::string CleanReport::kept_part_doubt() const {
  const int kept_faces = faces_before_cut - faces_outside_part;
  if (parts_dropped == 0 || most_faces_dropped_part <= kept_faces) return {};
  return "the part kept is the largest by area, yet a dropped part has " +
         count_of(most_faces_dropped_part, "face", "faces") + " to its " + std::to_string(kept_faces) +
         ": if that part is the model, the one kept is a stray piece (far off, or a corrupted coordinate) to "
         "delete in the modeller";
}

std::vector<std::string> CleanReport::messages() const {
  std::vector<std::string> out;
  if (welded_vertices > 0) {
    out.push_back("welded " + count_of(welded_vertices, "duplicate vertex", "duplicate vertices"));
  }
  if (degenerate_faces_dropped > 0) {
    out.push_back("dropped " + count_of(degenerate_faces_dropped, "degenerate face", "degenerate faces") +
                  " (a corner used twice)");
  }
  if (duplicate_faces_dropped > 0) {
    out.push_back("dropped " + count_of(duplicate_faces_dropped, "duplicate face", "duplicate faces"));
  }
  if (nonmanifold_edges_cut > 0 || parts_dropped > 0) {
    // "manifold" and the cut only when there were non-manifold edges to cut.
    const bool cut = nonmanifold_edges_cut > 0;
    out.push_back(std::string(cut ? "kept the largest manifold part (" : "kept the largest part (") +
                  std::to_string(faces_before_cut - faces_outside_part) + " of " +
                  count_of(faces_before_cut, "face", "faces") + "): " +
                  (cut ? "cut at " + count_of(nonmanifold_edges_cut, "non-manifold edge", "non-manifold edges") + ", "
                       : std::string()) +
                  "dropped " + count_of(faces_outside_part, "face", "faces") + " in " +
                  count_of(parts_dropped, "other part", "other parts"));
    const std::string doubt = kept_part_doubt();
    if (!doubt.empty()) out.back() += "; " + doubt;
  }
  if (slivers_removed > 0) {
    out.push_back("removed " + count_of(slivers_removed, "sliver face", "sliver faces") +
                  " (zero area or needle-thin) by collapsing or flipping edges");
  }
  if (holes_filled > 0) {
    out.push_back("filled " + count_of(holes_filled, "hole", "holes") + " with " +
                  count_of(hole_faces_added, "face", "faces"));
  }
  if (zero_area_faces > 0) {
    out.push_back("kept " + count_of(zero_area_faces, "face", "faces") + " with zero area (" +
                  (zero_area_faces == 1 ? "it carries" : "they carry") + " no weight)");
  }
  if (nonmanifold_vertices_split > 0) {
    out.push_back("split " + count_of(nonmanifold_vertices_split, "non-manifold vertex", "non-manifold vertices") +
                  " where parts touched at a single point");
  }
  if (faces_flipped > 0) {
    out.push_back("flipped " + count_of(faces_flipped, "face", "faces") +
                  " to make the orientation consistent (closed parts facing outward)");
  }
  if (unreferenced_vertices_removed > 0) {
    out.push_back("removed " + count_of(unreferenced_vertices_removed, "unused vertex", "unused vertices"));
  }
  if (components > 1) {
    out.push_back("the mesh has " + std::to_string(components) + " disconnected parts");
  }
  return out;
}

CleanMesh clean_mesh(const TriMesh& input, const CleanOptions& options) {
  CleanMesh out;
  CleanReport& report = out.report;
  const int n = input.num_vertices();
  report.input_vertices = n;
  report.input_faces = input.num_faces();
  if (input.triangles.empty()) throw InputError("the mesh has no faces");
  if (!std::isfinite(options.weld_tolerance) || options.weld_tolerance < 0.0) {
    throw InputError("the weld tolerance must be a finite number >= 0");
  }
  if (options.fill_holes_max_edges < 0 || options.fill_holes_max_edges > detail::kMaxFillEdges) {
    throw InputError("holes to fill must have 0 (off) to " + std::to_string(detail::kMaxFillEdges) + " edges, got " +
                     std::to_string(options.fill_holes_max_edges));
  }
  require_finite(input.positions);
  detail::require_valid_indices(input.triangles, n, /*require_distinct=*/false);

  // Weld: representatives are input vertices, so messages below name input vertices.
  const std::vector<int> rep = weld(input, options.weld_tolerance);
  for (int v = 0; v < n; ++v) report.welded_vertices += rep[static_cast<size_t>(v)] != v ? 1 : 0;
  std::vector<Triangle> welded(input.triangles.size());
  for (size_t f = 0; f < welded.size(); ++f) {
    for (size_t i = 0; i < 3; ++i) {
      welded[f][i] = rep[static_cast<size_t>(input.triangles[f][i])];
    }
  }

  FaceFilter filter = filter_faces(welded, n);
  report.degenerate_faces_dropped = filter.degenerate;
  report.duplicate_faces_dropped = filter.duplicate;
  if (filter.kept.empty()) {
    throw InputError("no usable faces left after clean-up (all " + std::to_string(report.input_faces) +
                     " faces were degenerate)");
  }
  std::vector<Triangle> tris(filter.kept.size());
  for (size_t k = 0; k < tris.size(); ++k) tris[k] = welded[static_cast<size_t>(filter.kept[k])];
  welded = {};
  const std::vector<char> used_before_cut = keep_manifold_part(tris, filter.kept, input.positions, options, report,
                                                               input.triangles.size(), out.input_face_outside_part);
  // Welded (a soup's triangles joined) and down to the largest part when asked: only then is a
  // far-off part or a stray vertex told from a model in a wrong unit.
  require_workable_extent(input.positions, tris);

  const HalfEdgeGroups groups = detail::group_half_edges(tris, n);

  std::vector<int> copy_origin;
  report.nonmanifold_vertices_split = split_nonmanifold_vertices(tris, groups, n, copy_origin);

  // Compact: referenced vertices in their current order (split copies last). Orienting
  // after renumbering is the same, and builds the positions once.
  const size_t total = static_cast<size_t>(n) + copy_origin.size();
  const auto origin = [&](size_t v) {
    return v < static_cast<size_t>(n) ? static_cast<int>(v) : copy_origin[v - static_cast<size_t>(n)];
  };
  std::vector<int> new_index(total, -1);
  for (const Triangle& t : tris) {
    for (int v : t) new_index[static_cast<size_t>(v)] = 0;
  }
  std::vector<int> vertex_name;  // cleaned vertex -> input vertex, for messages
  vertex_name.reserve(total);
  for (size_t v = 0; v < total; ++v) {
    if (new_index[v] < 0) {
      // Only input vertices can be unreferenced (a copy exists because a face uses it).
      const bool cut_away = !used_before_cut.empty() && v < used_before_cut.size() && used_before_cut[v];
      report.unreferenced_vertices_removed += v < static_cast<size_t>(n) && rep[v] == static_cast<int>(v) && !cut_away ? 1 : 0;
      continue;
    }
    new_index[v] = static_cast<int>(vertex_name.size());
    vertex_name.push_back(origin(v));
  }
  out.mesh.positions.resize(vertex_name.size());
  for (size_t v = 0; v < vertex_name.size(); ++v) {
    out.mesh.positions[v] = input.positions[static_cast<size_t>(vertex_name[v])];
  }
  for (Triangle& t : tris) {
    for (int& v : t) v = new_index[static_cast<size_t>(v)];
  }
  out.mesh.triangles = std::move(tris);

  const detail::OrientResult orient =
      detail::orient_faces(out.mesh.triangles, groups, out.mesh.positions, vertex_name, options.orient_closed_outward);
  report.faces_flipped = orient.faces_flipped;
  report.components = orient.components;

  out.face_source = std::move(filter.kept);
  out.input_face_to_clean.assign(input.triangles.size(), -1);
  for (size_t k = 0; k < out.face_source.size(); ++k) {
    out.input_face_to_clean[static_cast<size_t>(out.face_source[k])] = static_cast<int>(k);
  }
  out.input_vertex_to_clean.resize(static_cast<size_t>(n));
  for (size_t v = 0; v < static_cast<size_t>(n); ++v) {
    out.input_vertex_to_clean[v] = new_index[static_cast<size_t>(rep[v])];
  }
  out.vertex_source = std::move(vertex_name);
  detail::repair_locally(out, options);
  report.zero_area_faces = count_zero_area(out.mesh.triangles, out.mesh.positions);
  // Refused by name: a far-off stray part (part_spread.h), then a far-off vertex in a part.
  const std::vector<int> roots = vertex_part_roots(out.mesh);
  require_compact_parts(out.mesh, roots);
  require_no_stray_vertex(out.mesh, out.vertex_source, roots);
  return out;
}

}  // namespace ff
