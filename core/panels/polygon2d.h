#pragma once
// Pure 2D polygon geometry for checking panels in their own planes: simplicity, kernel
// (star-shapedness), flipped edges (paper fig. 6 / 7f), triangulation, corner angles.
// Polygons are vertex lists, closed implicitly (last vertex connects to the first, not
// repeated). Tolerances are absolute lengths in the polygon's units.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

using Vec2 = Eigen::Vector2d;

// An orthonormal frame of a plane, right-handed: u x v = normal, so a polygon that is
// counter-clockwise in 2D is counter-clockwise seen from the side the normal points to.
struct PlaneFrame {
  Vec3 origin = Vec3::Zero();
  Vec3 u = Vec3::UnitX();
  Vec3 v = Vec3::UnitY();
  Vec3 normal = Vec3::UnitZ();

  // Orthogonal projection into the plane's coordinates.
  Vec2 to_2d(const Vec3& p) const {
    const Vec3 d = p - origin;
    return Vec2(d.dot(u), d.dot(v));
  }
  Vec3 to_3d(const Vec2& q) const { return origin + q.x() * u + q.y() * v; }
};

// Deterministic u (from the coordinate axis least aligned with the normal). The normal is
// normalised here; throws InputError if it is zero or not finite.
PlaneFrame make_plane_frame(const Vec3& origin, const Vec3& unit_normal);

// Sum of edge cross products of a 3D polygon (Newell): 2 * area * unit normal for a planar
// polygon, a robust average normal otherwise; zero for a degenerate one.
Vec3 newell_normal(const std::vector<Vec3>& polygon);

// Twice the cross product's z, i.e. > 0 when a -> b -> c turns left.
inline double orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Shoelace area; positive = counter-clockwise.
double signed_area(const std::vector<Vec2>& polygon);

// The mean of the vertices; zero for an empty list.
Vec2 vertex_average(const std::vector<Vec2>& polygon);

// Area centroid; the vertex average when the area is (near) zero. Zero for an empty list.
Vec2 polygon_centroid(const std::vector<Vec2>& polygon);

// True when the polygon has >= 3 vertices, no edge of length <= tol, no two non-adjacent
// edges closer than or equal to tol (crossing, touching, repeated vertices), and no two
// adjacent edges folding back onto each other (an end vertex within tol of the other edge).
// Either orientation. A sweep over x: near-linear for panels, O(k^2) worst case.
bool is_simple(const std::vector<Vec2>& polygon, double tol);

// The kernel (points that see the whole polygon) of a counter-clockwise polygon, eroded by
// tol: the convex polygon of points at least tol inside every edge's supporting line, by
// successive half-plane clipping of the bounding box, O(k * kernel size). Empty when that
// set is empty or has area <= tol^2, so a kernel of zero area counts as empty and any
// point of a non-empty kernel is a robust reference point. Zero-length edges are ignored.
// A clockwise polygon has an empty kernel.
std::vector<Vec2> polygon_kernel(const std::vector<Vec2>& ccw_polygon, double tol);
bool is_star_shaped(const std::vector<Vec2>& ccw_polygon, double tol);

// Whether p lies at least 4 tol inside every edge's line of the counter-clockwise polygon
// (tol > 0): then p is in polygon_kernel(polygon, tol), and so is the disk of radius 3 tol
// about it, whose area is above the tol^2 below which the kernel counts as empty. A cheap
// sufficient test, no clipping: the panel check asks it first. Zero-length edges are
// skipped, as polygon_kernel skips them.
bool clearly_in_kernel(const std::vector<Vec2>& ccw_polygon, const Vec2& p, double tol);

// The centroid of polygon_kernel(): a point well inside the kernel for flip detection. When
// the kernel is empty, the vertex average (check is_star_shaped() to tell the two apart, or
// compute the kernel once and take polygon_centroid() of it).
Vec2 kernel_point(const std::vector<Vec2>& ccw_polygon, double tol);

// Edges a -> b with triangle (reference, a, b) strictly clockwise (paper fig. 6 / 7f): their
// start indices (edge i runs from vertex i to vertex i + 1), and whether there is one (the
// panel check's hot path: no allocation, stops at the first).
std::vector<int> flipped_edges(const std::vector<Vec2>& polygon, const Vec2& reference);
bool has_flipped_edge(const std::vector<Vec2>& polygon, const Vec2& reference);

// Even-odd rule; points exactly on the boundary may go either way.
bool point_in_polygon(const std::vector<Vec2>& polygon, const Vec2& p);
double distance_point_segment(const Vec2& p, const Vec2& a, const Vec2& b);
// Distance to the nearest edge (infinity for an empty polygon).
double distance_to_boundary(const std::vector<Vec2>& polygon, const Vec2& p);

// k - 2 triangles (indices into the polygon) with the polygon's orientation (CCW for CCW
// input). Simple polygons (is_simple with tol 0): ear clipping, O(k^2), collinear vertices
// fine. Non-simple polygons: a fan from vertex 0 (covers the polygon's winding, not a
// proper triangulation). Fewer than 3 vertices: none.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& polygon);

// Smallest interior angle in degrees, each in (0, 360): reflex corners > 180, collinear
// 180. The interior is the left side for CCW polygons, the right side for CW ones. A corner
// with a zero-length edge counts as 0. Returns 0 for fewer than 3 vertices.
double min_interior_angle_deg(const std::vector<Vec2>& polygon);
// The same with its corner: the vertex index (the first on ties; -1 for fewer than 3 vertices).
struct PolygonCorner {
  double angle_deg = 0.0;
  int index = -1;
};
PolygonCorner smallest_interior_angle(const std::vector<Vec2>& polygon);

}  // namespace ff
