#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/topology.h"
#include "core/shapes/hard_cases.h"
#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {
namespace {

// Two vertices closer than `tolerance`, by a sweep along x.
bool has_near_duplicate_vertices(const TriMesh& m, double tolerance) {
  std::vector<Vec3> p = m.positions;
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); });
  for (size_t i = 0; i < p.size(); ++i) {
    for (size_t j = i + 1; j < p.size() && p[j].x() - p[i].x() <= tolerance; ++j) {
      if ((p[j] - p[i]).norm() <= tolerance) return true;
    }
  }
  return false;
}

// Every directed edge once, and every interior edge used once in each direction.
void expect_consistent_orientation(const TriMesh& m, const MeshTopology& t) {
  std::set<std::pair<int, int>> directed;
  for (const Triangle& tri : m.triangles) {
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_TRUE(directed.insert({tri[i], tri[(i + 1) % 3]}).second) << "directed edge used twice";
    }
  }
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.is_boundary_edge(e)) continue;
    const auto& ev = t.edge_vertices[static_cast<size_t>(e)];
    EXPECT_TRUE(directed.count({ev[0], ev[1]}) && directed.count({ev[1], ev[0]})) << "edge " << e;
  }
}

// Where the torus (major radius R around z) is closest to p: the middle of its tube there.
Vec3 tube_centre(const Vec3& p, double major_radius) {
  const Eigen::Vector2d xy(p.x(), p.y());
  const Eigen::Vector2d c = major_radius * xy.normalized();
  return Vec3(c.x(), c.y(), 0.0);
}

// Area of a height field over [-half, half]^2 (minus the disk of radius `hole`) by the
// midpoint rule, from its gradient.
double height_field_area(double half, double hole, const std::function<Eigen::Vector2d(double, double)>& gradient) {
  const int n = 2000;
  const double h = 2.0 * half / n;
  double area = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = -half + (i + 0.5) * h, y = -half + (j + 0.5) * h;
      if (x * x + y * y < hole * hole) continue;
      area += std::sqrt(1.0 + gradient(x, y).squaredNorm()) * h * h;
    }
  }
  return area;
}

TEST(HardCases, NamesAndOrder) {
  std::vector<std::string> names;
  for (const NamedShape& s : hard_cases(500)) names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"saddle", "helicoid", "twisted_strip", "bump", "torus", "groin_vault",
                                             "roof_with_hole", "barrel_vault", "monkey_saddle", "cone"}));
}

TEST(HardCases, CleanManifoldOrientedWithExpectedTopology) {
  for (const NamedShape& s : hard_cases(4000)) {
    SCOPED_TRACE(s.name);
    const TriMesh& m = s.mesh;
    MeshTopology t;
    ASSERT_NO_THROW(t = build_topology(m));
    EXPECT_EQ(t.num_components, 1);
    EXPECT_EQ(euler_characteristic(m, t), s.euler_characteristic);
    EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), s.boundary_loops);
    expect_consistent_orientation(m, t);

    // Every vertex used, none duplicated (seams joined through indices, not by distance).
    std::vector<bool> used(m.positions.size(), false);
    for (const Triangle& tri : m.triangles) {
      for (int v : tri) used[static_cast<size_t>(v)] = true;
    }
    EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
    EXPECT_FALSE(has_near_duplicate_vertices(m, 1e-6 * bbox_diagonal(m)));

    // Nothing for clean_mesh to repair.
    const CleanMesh cleaned = clean_mesh(m);
    EXPECT_TRUE(cleaned.report.messages().empty());
    EXPECT_EQ(cleaned.mesh.num_faces(), m.num_faces());
    EXPECT_EQ(cleaned.report.faces_flipped, 0);

    // No degenerate or sliver-thin faces.
    const double mean_area = total_area(m) / m.num_faces();
    double min_area = mean_area;
    for (int f = 0; f < m.num_faces(); ++f) min_area = std::min(min_area, face_area(m, f));
    EXPECT_GT(min_area, 0.05 * mean_area);

    // Normals: up on the open shapes (every face), outward on the torus.
    if (s.name == "torus") {
      for (int f = 0; f < m.num_faces(); ++f) {
        const Vec3 c = face_centroid(m, f);
        EXPECT_GT(face_normal(m, f).dot(c - tube_centre(c, 10.0)), 0.0) << "face " << f;
      }
    } else {
      for (int f = 0; f < m.num_faces(); ++f) EXPECT_GT(face_normal(m, f).z(), 0.0) << "face " << f;
    }
  }
}

TEST(HardCases, TriangleCountNearRequest) {
  for (int request : {500, 4000, 20000}) {
    for (const NamedShape& s : hard_cases(request)) {
      EXPECT_NEAR(s.mesh.num_faces(), request, 0.15 * request) << s.name << " at " << request;
    }
  }
}

TEST(HardCases, Deterministic) {
  const auto a = hard_cases(1000), b = hard_cases(1000);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].mesh.triangles, b[i].mesh.triangles) << a[i].name;
    EXPECT_EQ(a[i].mesh.positions, b[i].mesh.positions) << a[i].name;
  }
}

TEST(HardCases, AreasMatchTheSurfaces) {
  const int n = 8000;
  // Torus: 4 pi^2 R r.
  EXPECT_NEAR(total_area(make_torus(n)), 4.0 * kPi * kPi * 10.0 * 3.0, 0.01 * 4.0 * kPi * kPi * 30.0);

  // Helicoid: integral of sqrt(r^2 + p^2) dr dt.
  {
    const double p = 12.0 / (2.0 * kPi);
    const auto F = [p](double r) { return (r * std::hypot(r, p) + p * p * std::asinh(r / p)) / 2.0; };
    const double expected = 2.0 * kPi * (F(10.0) - F(4.0));
    EXPECT_NEAR(total_area(make_helicoid(n)), expected, 0.01 * expected);
  }
  // Twisted strip: length * integral of sqrt(1 + k^2 t^2) dt, k = twist / length.
  {
    const double length = 24.0, w = 3.0, k = (kPi / 2.0) / length;
    const double expected = length * (w * std::sqrt(1.0 + k * k * w * w) + std::asinh(k * w) / k);
    EXPECT_NEAR(total_area(make_twisted_strip(n)), expected, 0.01 * expected);
  }
  // Barrel vault: a half cylinder of radius 6, 24 long.
  EXPECT_NEAR(total_area(make_barrel_vault(n)), kPi * 6.0 * 24.0, 0.01 * kPi * 6.0 * 24.0);
  // Groin vault: 4 cylinder pieces over triangles, 8 rho (a phi - rise) with a = 6, rise = 4.
  {
    const double a = 6.0, rise = 4.0, rho = (a * a + rise * rise) / (2.0 * rise), phi = std::asin(a / rho);
    const double expected = 8.0 * rho * (a * phi - rise);
    EXPECT_NEAR(total_area(make_groin_vault(n)), expected, 0.01 * expected);
  }
  // Height fields by numerical integration.
  {
    const double expected = height_field_area(
        10.0, 0.0, [](double x, double y) { return Eigen::Vector2d(2.0 * 3.0 * x / 100.0, -2.0 * 3.0 * y / 100.0); });
    EXPECT_NEAR(total_area(make_saddle(n)), expected, 0.01 * expected);
  }
  {
    const double expected = height_field_area(10.0, 0.0, [](double x, double y) {
      const double z = 3.0 * std::exp(-(x * x + y * y) / (2.0 * 2.5 * 2.5));
      return Eigen::Vector2d(-x / (2.5 * 2.5) * z, -y / (2.5 * 2.5) * z);
    });
    const double area = total_area(make_bump(n));
    EXPECT_NEAR(area, expected, 0.01 * expected);
    EXPECT_GT(area, 400.0) << "the bump adds area to the flat square";
  }
  {
    const double half = 15.0;
    const double expected = height_field_area(half, 5.0, [half](double x, double y) {
      const double xi = x / half, eta = y / half;
      return Eigen::Vector2d(3.0 * (-1.2 * xi + 0.15 * eta) / half, 3.0 * (-0.8 * eta + 0.15 * xi) / half);
    });
    EXPECT_NEAR(total_area(make_roof_with_hole(n)), expected, 0.01 * expected);
  }
  {
    const double expected = height_field_area(10.0, 0.0, [](double x, double y) {
      return Eigen::Vector2d(3.0 * (3.0 * x * x - 3.0 * y * y) / 1000.0, 3.0 * (-6.0 * x * y) / 1000.0);
    });
    EXPECT_NEAR(total_area(make_monkey_saddle(n)), expected, 0.01 * expected);
  }
  // Cone: the slope is the same everywhere, so the area is the square's times sqrt(1 + s^2).
  EXPECT_NEAR(total_area(make_cone(n)), 400.0 * std::sqrt(1.0 + 0.6 * 0.6), 0.01 * 400.0 * std::sqrt(1.36));
}

// The cone's apex and the monkey saddle's flat point are mesh vertices, where the hard part is.
TEST(HardCases, ConeApexAndMonkeySaddleFlatPointAreVertices) {
  for (int request : {1, 1000, 8000}) {
    const TriMesh cone = make_cone(request);
    const TriMesh monkey = make_monkey_saddle(request);
    const auto has = [](const TriMesh& m, const Vec3& p) {
      return std::any_of(m.positions.begin(), m.positions.end(), [&](const Vec3& q) { return (q - p).norm() < 1e-12; });
    };
    EXPECT_TRUE(has(cone, Vec3(0.0, 0.0, 6.0))) << request;
    EXPECT_TRUE(has(monkey, Vec3::Zero())) << request;
  }
}

TEST(HardCases, GroinVaultCreasesAreSharpEdgesOnTheDiagonals) {
  const TriMesh m = make_groin_vault(4000);
  const MeshTopology t = build_topology(m);
  const auto on_diagonal = [&](int v) {
    const Vec3& p = m.positions[static_cast<size_t>(v)];
    return std::abs(p.x()) == std::abs(p.y());
  };
  // No triangle crosses a crease: each lies where |x| <= |y| or where |y| <= |x|.
  for (const Triangle& tri : m.triangles) {
    bool x_side = true, y_side = true;
    for (int v : tri) {
      const Vec3& p = m.positions[static_cast<size_t>(v)];
      x_side = x_side && std::abs(p.y()) <= std::abs(p.x());
      y_side = y_side && std::abs(p.x()) <= std::abs(p.y());
    }
    EXPECT_TRUE(x_side || y_side);
  }
  // The normals jump across the diagonal edges (toward the corners) and nowhere else.
  double crease_max = 0.0, smooth_max = 0.0;
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.is_boundary_edge(e)) continue;
    const auto& ef = t.edge_faces[static_cast<size_t>(e)];
    const double angle = std::acos(std::clamp(face_normal(m, ef[0]).dot(face_normal(m, ef[1])), -1.0, 1.0));
    const auto& ev = t.edge_vertices[static_cast<size_t>(e)];
    double& slot = on_diagonal(ev[0]) && on_diagonal(ev[1]) ? crease_max : smooth_max;
    slot = std::max(slot, angle);
  }
  EXPECT_GT(crease_max, 60.0 * kPi / 180.0);
  EXPECT_LT(smooth_max, 10.0 * kPi / 180.0);
  // The springings: the four corners at z = 0, the crown at the rise.
  double lowest = 1e9, highest = -1e9;
  for (const Vec3& p : m.positions) {
    lowest = std::min(lowest, p.z());
    highest = std::max(highest, p.z());
  }
  EXPECT_NEAR(lowest, 0.0, 1e-9);
  EXPECT_NEAR(highest, 4.0, 1e-9);
}

TEST(HardCases, RoofHoleIsACircleAndTheOutlineASquareWithCornerVertices) {
  const TriMesh m = make_roof_with_hole(3000, 30.0, 5.0);
  const MeshTopology t = build_topology(m);
  ASSERT_EQ(t.boundary_loops.size(), 2u);
  int on_circle = 0, on_square = 0;
  for (const auto& loop : t.boundary_loops) {
    bool circle = true, square = true;
    for (int v : loop) {
      const Vec3& p = m.positions[static_cast<size_t>(v)];
      circle = circle && std::abs(std::hypot(p.x(), p.y()) - 5.0) < 1e-9;
      square = square && std::abs(std::max(std::abs(p.x()), std::abs(p.y())) - 15.0) < 1e-9;
    }
    on_circle += circle;
    on_square += square;
  }
  EXPECT_EQ(on_circle, 1);
  EXPECT_EQ(on_square, 1);
  int corners = 0;
  for (const Vec3& p : m.positions) {
    corners += std::abs(std::abs(p.x()) - 15.0) < 1e-12 && std::abs(std::abs(p.y()) - 15.0) < 1e-12;
  }
  EXPECT_EQ(corners, 4);
}

TEST(HardCases, SaddleCentreIsASaddlePoint) {
  // The centre is a vertex at z = 0 whose one-ring goes both above and below it; the edge
  // midpoints sit at +-rise.
  const TriMesh m = make_saddle(2000, 20.0, 3.0);
  const MeshTopology t = build_topology(m);
  int centre = -1;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Vec3& p = m.positions[static_cast<size_t>(v)];
    if (p.head<2>().norm() < 1e-12) centre = v;
    if (std::abs(std::abs(p.x()) - 10.0) < 1e-12 && std::abs(p.y()) < 1e-12) {
      EXPECT_NEAR(p.z(), 3.0, 1e-9);
    }
    if (std::abs(std::abs(p.y()) - 10.0) < 1e-12 && std::abs(p.x()) < 1e-12) {
      EXPECT_NEAR(p.z(), -3.0, 1e-9);
    }
  }
  ASSERT_GE(centre, 0);
  EXPECT_NEAR(m.positions[static_cast<size_t>(centre)].z(), 0.0, 1e-12);
  bool above = false, below = false;
  for (int k = t.vertex_face_offsets[static_cast<size_t>(centre)];
       k < t.vertex_face_offsets[static_cast<size_t>(centre) + 1]; ++k) {
    for (int v : m.triangles[static_cast<size_t>(t.vertex_faces[static_cast<size_t>(k)])]) {
      above = above || m.positions[static_cast<size_t>(v)].z() > 1e-9;
      below = below || m.positions[static_cast<size_t>(v)].z() < -1e-9;
    }
  }
  EXPECT_TRUE(above && below);
}

TEST(HardCases, BadParametersThrow) {
  EXPECT_THROW(make_helicoid(1000, 5.0, 4.0), InputError);
  EXPECT_THROW(make_helicoid(1000, 0.0, 4.0), InputError);
  EXPECT_THROW(make_torus(1000, 2.0, 3.0), InputError);
  EXPECT_THROW(make_groin_vault(1000, 12.0, 7.0), InputError);
  EXPECT_THROW(make_barrel_vault(1000, 24.0, 12.0, 0.0), InputError);
  EXPECT_THROW(make_roof_with_hole(1000, 30.0, 15.0), InputError);
  EXPECT_THROW(make_saddle(1000, -1.0), InputError);
  EXPECT_THROW(make_monkey_saddle(1000, 0.0), InputError);
  EXPECT_THROW(make_cone(1000, -2.0), InputError);
}

TEST(HardCases, TinyRequestsStillGiveValidMeshes) {
  for (const NamedShape& s : hard_cases(1)) {
    SCOPED_TRACE(s.name);
    MeshTopology t;
    ASSERT_NO_THROW(t = build_topology(s.mesh));
    EXPECT_EQ(euler_characteristic(s.mesh, t), s.euler_characteristic);
    EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), s.boundary_loops);
  }
}

}  // namespace
}  // namespace ff
