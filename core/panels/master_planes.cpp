#include "core/panels/master_planes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/util/angles.h"

namespace ff {

namespace {

struct Group {
  Vec3 normal_sum = Vec3::Zero();
  Vec3 center_sum = Vec3::Zero();
  double area = 0.0;
  int members = 1;
  int fixed = -1;  // a member whose plane is fixed: the group keeps it
};

int find(std::vector<int>& parent, int x) {
  while (parent[static_cast<size_t>(x)] != x) {
    parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    x = parent[static_cast<size_t>(x)];
  }
  return x;
}

// Whether two planes meet near the pair: their line closer to the middle of their centres
// than kNearLineShare of the centres' distance. Measured across the line: at that middle the
// two planes' signed distances differ by |ea - eb|, which grows by sin(angle) per unit of
// distance across it.
bool meet_near(const Plane& a, const Plane& b, const Vec3& center_a, const Vec3& center_b) {
  const Vec3 middle = 0.5 * (center_a + center_b);
  const double apart = std::abs(a.distance(middle) - b.distance(middle));
  const double sine = a.normal.cross(b.normal).norm();
  return apart < kNearLineShare * sine * (center_a - center_b).norm();
}

}  // namespace

MasterPlanes snap_master_planes(const std::vector<Plane>& planes, const std::vector<Vec3>& centers,
                                const std::vector<double>& areas, const std::vector<std::pair<int, int>>& neighbours,
                                double max_angle_deg, const std::vector<char>& fixed, const std::vector<char>& alone) {
  const size_t n = planes.size();
  const double cos_max = std::cos(max_angle_deg * kPi / 180.0);
  std::vector<Group> groups(n);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < n; ++i) {
    const double a = std::max(areas[i], 1e-300);
    const int kept = i < fixed.size() && fixed[i] ? static_cast<int>(i) : -1;
    groups[i] = Group{a * planes[i].normal, a * centers[i], a, 1, kept};
  }
  struct Candidate {
    double cosine;
    int a, b;
  };
  std::vector<Candidate> close;
  const auto single = [&](int c) { return static_cast<size_t>(c) < alone.size() && alone[static_cast<size_t>(c)]; };
  for (const auto& [a, b] : neighbours) {
    if (single(a) || single(b)) continue;
    const Plane& pa = planes[static_cast<size_t>(a)];
    const Plane& pb = planes[static_cast<size_t>(b)];
    const double c = pa.normal.dot(pb.normal);
    if (!(c > cos_max)) continue;
    if (meet_near(pa, pb, centers[static_cast<size_t>(a)], centers[static_cast<size_t>(b)])) continue;
    close.push_back({c, std::min(a, b), std::max(a, b)});
  }
  std::sort(close.begin(), close.end(), [](const Candidate& x, const Candidate& y) {
    if (x.cosine != y.cosine) return x.cosine > y.cosine;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for (const Candidate& c : close) {
    const int ra = find(parent, c.a), rb = find(parent, c.b);
    if (ra == rb) continue;
    Group& ga = groups[static_cast<size_t>(ra)];
    Group& gb = groups[static_cast<size_t>(rb)];
    if (ga.normal_sum.normalized().dot(gb.normal_sum.normalized()) <= cos_max) continue;
    // Two fixed planes stay as they are: they join only when they are the same plane.
    if (ga.fixed >= 0 && gb.fixed >= 0) {
      const Plane& pa = planes[static_cast<size_t>(ga.fixed)];
      const Plane& pb = planes[static_cast<size_t>(gb.fixed)];
      if (pa.normal != pb.normal || pa.offset != pb.offset) continue;
    }
    const int root = std::min(ra, rb), child = std::max(ra, rb);
    Group merged{ga.normal_sum + gb.normal_sum, ga.center_sum + gb.center_sum, ga.area + gb.area,
                 ga.members + gb.members, ga.fixed >= 0 ? ga.fixed : gb.fixed};
    groups[static_cast<size_t>(root)] = merged;
    parent[static_cast<size_t>(child)] = root;
  }
  MasterPlanes m;
  m.master_of.assign(n, -1);
  std::vector<int> id_of_root(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const int r = find(parent, static_cast<int>(i));
    if (id_of_root[static_cast<size_t>(r)] < 0) {
      id_of_root[static_cast<size_t>(r)] = static_cast<int>(m.planes.size());
      const Group& g = groups[static_cast<size_t>(r)];
      if (g.fixed >= 0) {
        m.planes.push_back(planes[static_cast<size_t>(g.fixed)]);
      } else if (g.members == 1) {
        m.planes.push_back(planes[i]);  // a group of one keeps its plane exactly
      } else {
        m.planes.push_back(Plane::through(g.center_sum / g.area, g.normal_sum.normalized()));
      }
      m.centers.push_back(g.center_sum / g.area);
      m.count.push_back(0);
    }
    m.master_of[i] = id_of_root[static_cast<size_t>(r)];
    m.count[static_cast<size_t>(m.master_of[i])] += 1;
  }
  return m;
}

}  // namespace ff
