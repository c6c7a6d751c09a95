// The gap filling's geometry (core/fabricate/sheet_nesting.h): its quick proximity test
// against the tests' own polygon distance. The packing's guarantees with gap filling are
// checked in test_cut_sheets.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fabricate/sheet_nesting.h"
#include "core/util/random.h"
#include "cut_sheet_checks.h"

namespace ff {
namespace {

// The gap filling's quick test says what the full distance says, on random polygon pairs
// (convex and not, apart, near, crossing, nested) at spacings around their distance.
TEST(SheetNesting, QuickProximityTestAgreesWithTheDistance) {
  SplitMix64 rng(5);
  const auto star = [&](const Vec2& centre, double radius, int n) {
    cut_sheet_test::Poly p;
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * kPi * i / n, r = radius * (0.4 + 0.6 * rng.uniform());
      p.push_back(centre + r * Vec2(std::cos(angle), std::sin(angle)));
    }
    return p;
  };
  int closer = 0, not_closer = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const cut_sheet_test::Poly a = star(Vec2::Zero(), 1.0, 3 + trial % 9);
    const Vec2 centre(4.0 * rng.uniform() - 2.0, 4.0 * rng.uniform() - 2.0);
    const cut_sheet_test::Poly b = star(centre, 0.2 + rng.uniform(), 3 + trial % 7);
    const double d = cut_sheet_test::polygon_distance(a, b);  // the tests' own
    for (const double spacing : {d * 0.5, d * (1.0 - 1e-12), d, d * (1.0 + 1e-12), d * 2.0, 0.01, 0.3}) {
      if (!(spacing > 0.0)) continue;
      const bool expected = d < spacing;
      EXPECT_EQ(polygons_closer_than(a, b, spacing), expected) << "trial " << trial << " spacing " << spacing;
      ++(expected ? closer : not_closer);
    }
  }
  EXPECT_GT(closer, 1000);
  EXPECT_GT(not_closer, 1000);
}

}  // namespace
}  // namespace ff
