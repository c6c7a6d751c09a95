#include "core/panels/glass_split.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/panels/panel_check.h"

namespace ff {

namespace {

using Piece = std::vector<int>;

// The angles a diagonal a-b cuts the corners of `piece` (positions ia, ib) into.
struct Cut {
  bool ok = false;
  double parts[4] = {0, 0, 0, 0};  // at a (towards prev, towards next), at b (same)
};

double angle_at(const std::vector<Vec2>& p, int prev, int at, int next) {
  return corner_angle_deg(p[static_cast<size_t>(prev)], p[static_cast<size_t>(at)], p[static_cast<size_t>(next)]);
}

bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tol) {
  const double d1 = orient2d(a, b, c), d2 = orient2d(a, b, d), d3 = orient2d(c, d, a), d4 = orient2d(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return distance_point_segment(c, a, b) <= tol || distance_point_segment(d, a, b) <= tol;
}

// Whether a-b is a diagonal of the piece: inside the corner at both ends (both parts of each
// corner open) and clear of every edge not at a or b.
Cut try_cut(const std::vector<Vec2>& p, const Piece& piece, size_t ia, size_t ib, double tol) {
  Cut cut;
  const size_t n = piece.size();
  const int a = piece[ia], b = piece[ib];
  const int a_prev = piece[(ia + n - 1) % n], a_next = piece[(ia + 1) % n];
  const int b_prev = piece[(ib + n - 1) % n], b_next = piece[(ib + 1) % n];
  const double corner_a = angle_at(p, a_prev, a, a_next), corner_b = angle_at(p, b_prev, b, b_next);
  cut.parts[0] = angle_at(p, a_prev, a, b);
  cut.parts[1] = angle_at(p, b, a, a_next);
  cut.parts[2] = angle_at(p, b_prev, b, a);
  cut.parts[3] = angle_at(p, a, b, b_next);
  constexpr double kOpen = 1e-7;  // degrees: a part this thin is a cut along an edge
  for (double part : cut.parts) {
    if (!(part > kOpen)) return cut;
  }
  if (std::abs(cut.parts[0] + cut.parts[1] - corner_a) > 1e-6) return cut;
  if (std::abs(cut.parts[2] + cut.parts[3] - corner_b) > 1e-6) return cut;
  for (size_t e = 0; e < n; ++e) {
    const int u = piece[e], v = piece[(e + 1) % n];
    if (u == a || u == b || v == a || v == b) continue;
    if (segments_touch(p[static_cast<size_t>(a)], p[static_cast<size_t>(b)], p[static_cast<size_t>(u)],
                       p[static_cast<size_t>(v)], tol))
      return cut;
  }
  cut.ok = true;
  return cut;
}

// Lexicographic: every new corner >= min_deg, the reflex corner resolved, the smallest new angle.
struct Score {
  int meets = -1, resolves = -1;
  double smallest = -1.0;
  bool operator>(const Score& o) const {
    if (meets != o.meets) return meets > o.meets;
    if (resolves != o.resolves) return resolves > o.resolves;
    return smallest > o.smallest;
  }
};

Score score_of(const Cut& cut, double min_deg) {
  const double smallest = *std::min_element(cut.parts, cut.parts + 4);
  const bool resolves = cut.parts[0] <= 180.0 + kReflexSlackDeg && cut.parts[1] <= 180.0 + kReflexSlackDeg;
  return Score{smallest >= min_deg ? 1 : 0, resolves ? 1 : 0, smallest};
}

// The two pieces of `piece` cut along positions ia-ib.
std::pair<Piece, Piece> cut_piece(const Piece& piece, size_t ia, size_t ib) {
  const size_t n = piece.size();
  Piece first, second;
  for (size_t k = ia;; k = (k + 1) % n) {
    first.push_back(piece[k]);
    if (k == ib) break;
  }
  for (size_t k = ib;; k = (k + 1) % n) {
    second.push_back(piece[k]);
    if (k == ia) break;
  }
  return {first, second};
}

std::vector<Vec2> points_of(const std::vector<Vec2>& p, const Piece& piece) {
  std::vector<Vec2> out;
  for (int i : piece) out.push_back(p[static_cast<size_t>(i)]);
  return out;
}

}  // namespace

std::vector<std::vector<int>> convex_pieces(const std::vector<Vec2>& polygon, double min_deg) {
  std::vector<Piece> done;
  const size_t n = polygon.size();
  Piece whole(n);
  for (size_t i = 0; i < n; ++i) whole[i] = static_cast<int>(i);
  if (n < 4) return {whole};
  double extent = 0.0;
  for (const Vec2& q : polygon) extent = std::max(extent, (q - polygon[0]).norm());
  const double tol = 1e-12 * extent;
  std::vector<Piece> todo{whole};  // a stack: pieces come out in outline order
  while (!todo.empty()) {
    Piece piece = std::move(todo.back());
    todo.pop_back();
    const std::vector<int> reflex = reflex_corners(points_of(polygon, piece));
    if (reflex.empty() || piece.size() < 4) {
      done.push_back(std::move(piece));
      continue;
    }
    // The best cut from any reflex corner (panels have few corners: this is cheap).
    size_t best_a = 0, best_b = 0;
    Score best;
    for (int r : reflex) {
      const size_t ia = static_cast<size_t>(r);
      for (size_t k = 2; k + 1 < piece.size(); ++k) {
        const size_t ib = (ia + k) % piece.size();
        const Cut cut = try_cut(polygon, piece, ia, ib, tol);
        if (!cut.ok) continue;
        const Score s = score_of(cut, min_deg);
        if (s > best) best = s, best_a = ia, best_b = ib;
      }
    }
    if (best.meets < 0) {
      done.push_back(std::move(piece));  // left concave, and counted so by the report
      continue;
    }
    auto [first, second] = cut_piece(piece, best_a, best_b);
    todo.push_back(std::move(second));
    todo.push_back(std::move(first));
  }
  return done;
}

std::vector<int> acute_corners_after_split(const std::vector<Vec2>& polygon, double min_deg, bool glass) {
  if (!glass || reflex_corners(polygon).empty()) return acute_corners(polygon, min_deg);
  std::vector<char> acute(polygon.size(), 0);
  for (const Piece& piece : convex_pieces(polygon, min_deg)) {
    for (int i : acute_corners(points_of(polygon, piece), min_deg))
      acute[static_cast<size_t>(piece[static_cast<size_t>(i)])] = 1;
  }
  std::vector<int> out;
  for (size_t i = 0; i < acute.size(); ++i) {
    if (acute[i]) out.push_back(static_cast<int>(i));
  }
  return out;
}

int split_concave_panels(PanelMesh& pm, const TriMesh& mesh, double min_deg) {
  const size_t np = pm.panels.size();
  PanelMesh out = pm;
  out.panels.clear(), out.plane_normals.clear(), out.plane_offsets.clear(), out.panel_cluster.clear();
  out.issues.clear(), out.panel_source.clear();
  // Per original panel: its pieces' new indices and 2D outlines (for moving its faces).
  std::vector<std::vector<int>> piece_ids(np);
  std::vector<std::vector<std::vector<Vec2>>> piece_outlines(np);
  std::vector<PlaneFrame> frames(np);
  int split = 0;
  for (size_t p = 0; p < np; ++p) {
    const std::vector<int>& poly = pm.panels[p];
    const Vec3 normal = pm.plane_normals[p];
    const double offset = p < pm.plane_offsets.size() ? pm.plane_offsets[p] : 0.0;
    frames[p] = make_plane_frame(offset * normal, normal);
    std::vector<Vec2> outline;
    for (int v : poly) outline.push_back(frames[p].to_2d(pm.vertices[static_cast<size_t>(v)]));
    const PanelIssues& issues = pm.issues[p];
    std::vector<std::vector<int>> pieces{};
    const bool can_split = !issues.not_simple && !issues.flipped && !issues.too_few_vertices;
    if (can_split && !reflex_corners(outline).empty()) pieces = convex_pieces(outline, min_deg);
    if (pieces.empty()) {
      std::vector<int> all(poly.size());
      for (size_t i = 0; i < poly.size(); ++i) all[i] = static_cast<int>(i);
      pieces.push_back(all);
    }
    split += pieces.size() > 1 ? 1 : 0;
    for (const std::vector<int>& piece : pieces) {
      std::vector<int> vertices;
      std::vector<Vec2> piece_outline;
      for (int i : piece) {
        vertices.push_back(poly[static_cast<size_t>(i)]);
        piece_outline.push_back(outline[static_cast<size_t>(i)]);
      }
      PanelIssues piece_issues = issues;
      if (min_deg > 0.0 && pieces.size() > 1)
        piece_issues.acute_corner = !acute_corners(piece_outline, min_deg).empty();
      piece_ids[p].push_back(out.num_panels());
      piece_outlines[p].push_back(piece_outline);
      out.panels.push_back(std::move(vertices));
      out.plane_normals.push_back(normal);
      if (!pm.plane_offsets.empty()) out.plane_offsets.push_back(offset);
      if (!pm.panel_cluster.empty()) out.panel_cluster.push_back(pm.panel_cluster[p]);
      out.issues.push_back(piece_issues);
      out.panel_source.push_back(static_cast<int>(p));
    }
  }
  // Each face to the piece over its centroid (else the nearest piece).
  for (size_t f = 0; f < out.face_panel.size(); ++f) {
    const int p = pm.face_panel[f];
    if (p < 0 || piece_ids[static_cast<size_t>(p)].size() < 2) {
      if (p >= 0) out.face_panel[f] = piece_ids[static_cast<size_t>(p)][0];
      continue;
    }
    const auto& t = mesh.triangles[f];
    const Vec3 centroid = (mesh.positions[static_cast<size_t>(t[0])] + mesh.positions[static_cast<size_t>(t[1])] +
                           mesh.positions[static_cast<size_t>(t[2])]) /
                          3.0;
    const Vec2 q = frames[static_cast<size_t>(p)].to_2d(centroid);
    const auto& outlines = piece_outlines[static_cast<size_t>(p)];
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < outlines.size(); ++k) {
      const double d = point_in_polygon(outlines[k], q) ? -1.0 : distance_to_boundary(outlines[k], q);
      if (d < best_distance) best_distance = d, best = k;
      if (d < 0.0) break;
    }
    out.face_panel[f] = piece_ids[static_cast<size_t>(p)][best];
  }
  pm = std::move(out);
  return split;
}

}  // namespace ff
