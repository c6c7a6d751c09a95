// Unit tests of the welding step of clean_mesh (core/mesh/weld.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/mesh/weld.h"
#include "core/util/random.h"

namespace ff {
namespace {

TEST(CleanMeshWeld, ToleranceDoesNotChain) {
  // 0 and 1 are within tolerance, 1 and 2 too, 0 and 2 not: 1 joins 0, 2 stays.
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(0.6, 0, 0), Vec3(1.2, 0, 0), Vec3(1.25, 0.1, 0),
                                    Vec3(0.5, 0.0, 0.0)};
  // Nearest earlier representative wins: 4 is 0.5 from 0 and 0.7 from 2.
  EXPECT_EQ(detail::weld_representatives(points, 1.0), (std::vector<int>{0, 0, 2, 2, 0}));
  // Coincident vertices stay together: 3 sits on 1, so it follows 1 into 0 although
  // representative 2 is nearer to it.
  const std::vector<Vec3> pair = {Vec3(0, 0, 0), Vec3(0.9, 0, 0), Vec3(1.6, 0, 0), Vec3(0.9, 0, 0)};
  EXPECT_EQ(detail::weld_representatives(pair, 1.0), (std::vector<int>{0, 0, 2, 0}));
  // Coordinates far beyond tolerance * 2^63 still weld correctly.
  const std::vector<Vec3> far = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(-1e300, 0, 0), Vec3(-1e300, 0, 0)};
  EXPECT_EQ(detail::weld_representatives(far, 1e-300), (std::vector<int>{0, 0, 2, 2}));
  // A tolerance far below the coordinates' precision (and a huge one) stay quick.
  const std::vector<Vec3> fine = {Vec3(1e10, 0, 0), Vec3(1e10, 1e-12, 0), Vec3(1e10, 1e-6, 0)};
  EXPECT_EQ(detail::weld_representatives(fine, 1e-11), (std::vector<int>{0, 0, 2}));
  EXPECT_EQ(detail::weld_representatives(fine, 1e300), (std::vector<int>{0, 0, 0}));
}

TEST(CleanMeshWeld, ExactKeepsTheLowestIndexPerPosition) {
  // Many copies per spot, interleaved, and -0.0 == 0.0 (spots 0 and 5 coincide).
  std::vector<Vec3> points;
  for (int i = 0; i < 5000; ++i) {
    const int spot = (i * 37) % 50;
    points.emplace_back(spot % 5 == 0 ? (i % 2 ? -0.0 : 0.0) : spot * 0.1, spot / 7, 1.0);
  }
  const auto brute_force = [&points](const std::vector<char>& weldable) {
    std::vector<int> rep(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      rep[i] = static_cast<int>(i);
      for (size_t j = 0; j < i && weldable[i]; ++j) {
        if (weldable[j] && points[j] == points[i]) {
          rep[i] = static_cast<int>(j);
          break;
        }
      }
    }
    return rep;
  };
  std::vector<char> weldable(points.size(), 1);
  EXPECT_EQ(detail::weld_representatives(points, 0.0), brute_force(weldable));
  // Vertices left out keep themselves and are never chosen.
  weldable[0] = 0;
  weldable[37] = 0;
  EXPECT_EQ(detail::weld_representatives(points, 0.0, weldable), brute_force(weldable));
}

TEST(CleanMeshWeld, ToleranceMatchesBruteForce) {
  // Clustered random points (with exact copies), against the definition in weld.h.
  SplitMix64 random(7);
  std::vector<Vec3> points;
  for (int i = 0; i < 3000; ++i) {
    if (i > 0 && random.below(4) == 0) {
      points.push_back(points[random.below(points.size())]);
    } else {
      points.emplace_back(std::floor(random.uniform() * 40) * 0.05 + random.uniform() * 0.02, random.uniform() * 0.3,
                          -5.0 + random.uniform() * 0.02);
    }
  }
  const double tol = 0.015;
  std::vector<int> expected(points.size());
  std::vector<int> reps;
  for (size_t i = 0; i < points.size(); ++i) {
    expected[i] = static_cast<int>(i);
    for (size_t j = 0; j < i; ++j) {
      if (points[j] == points[i]) {
        expected[i] = expected[j];
        break;
      }
    }
    if (expected[i] != static_cast<int>(i)) continue;
    double best = tol * tol;
    for (int r : reps) {
      const double d2 = (points[static_cast<size_t>(r)] - points[i]).squaredNorm();
      if (d2 < best || (d2 == best && expected[i] == static_cast<int>(i))) {
        best = d2;
        expected[i] = r;
      }
    }
    if (expected[i] == static_cast<int>(i)) reps.push_back(static_cast<int>(i));
  }
  ASSERT_GT(points.size() - reps.size(), 1000u);
  EXPECT_EQ(detail::weld_representatives(points, tol), expected);
}

}  // namespace
}  // namespace ff
