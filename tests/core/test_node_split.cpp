// Node splitting: the pairings of a k-cluster node are the triangulations of its k-gon.
// Checked as triangulations (edge counts, no crossing diagonals), by count (Catalan) and
// distinctness, and the order in which a panel's boundary meets the nodes of one position.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/panels/node_split.h"

namespace ff {
namespace {

bool contains(const NodeTriangle& t, int p) { return t[0] == p || t[1] == p || t[2] == p; }

// Empty string when `pairing` is a triangulation of the convex k-gon, else what is wrong.
std::string triangulation_error(const Pairing& pairing, int k) {
  if (static_cast<int>(pairing.size()) != k - 2) return "not k - 2 triangles";
  std::map<std::pair<int, int>, int> edge_count;
  for (const NodeTriangle& t : pairing) {
    if (!(0 <= t[0] && t[0] < t[1] && t[1] < t[2] && t[2] < k)) return "triple not sorted or out of range";
    ++edge_count[{t[0], t[1]}];
    ++edge_count[{t[1], t[2]}];
    ++edge_count[{t[0], t[2]}];
  }
  for (int i = 0; i < k; ++i) {
    const std::pair<int, int> side{std::min(i, (i + 1) % k), std::max(i, (i + 1) % k)};
    if (edge_count[side] != 1) return "polygon side not in exactly one triangle";
  }
  std::vector<std::pair<int, int>> diagonals;
  for (const auto& [e, count] : edge_count) {
    const bool side = e.second - e.first == 1 || (e.first == 0 && e.second == k - 1);
    if (side) continue;
    if (count != 2) return "diagonal not in exactly two triangles";
    diagonals.push_back(e);
  }
  if (static_cast<int>(diagonals.size()) != k - 3) return "not k - 3 diagonals";
  for (const auto& [a, b] : diagonals) {
    for (const auto& [c, d] : diagonals) {
      if ((a < c && c < b && b < d) || (c < a && a < d && d < b)) return "crossing diagonals";
    }
  }
  return "";
}

TEST(NodeSplit, PairingCountsAreCatalanThenFans) {
  const int catalan[] = {1, 1, 2, 5, 14, 42};  // Catalan(0..5)
  for (int k = 3; k <= 7; ++k) {
    EXPECT_EQ(static_cast<int>(node_pairings(k).size()), catalan[k - 2]) << "k = " << k;
  }
  for (int k = 8; k <= 10; ++k) EXPECT_EQ(static_cast<int>(node_pairings(k).size()), k) << "k = " << k;
}

TEST(NodeSplit, EveryPairingIsADistinctTriangulation) {
  for (int k = 3; k <= 10; ++k) {
    const std::vector<Pairing> pairings = node_pairings(k);
    std::set<std::set<NodeTriangle>> distinct;
    for (size_t p = 0; p < pairings.size(); ++p) {
      EXPECT_EQ(triangulation_error(pairings[p], k), "") << "k = " << k << " pairing " << p;
      distinct.insert(std::set<NodeTriangle>(pairings[p].begin(), pairings[p].end()));
    }
    EXPECT_EQ(distinct.size(), pairings.size()) << "k = " << k;
  }
}

TEST(NodeSplit, TheCheckerCatchesNonTriangulations) {
  // The checker itself must fail on crossing diagonals and on missing triangles.
  EXPECT_NE(triangulation_error({{0, 1, 2}, {0, 2, 3}}, 5), "");
  EXPECT_NE(triangulation_error({{0, 1, 3}, {0, 2, 3}}, 4), "");  // 1-3 and 0-2 cross
  EXPECT_NE(triangulation_error({{0, 2, 1}, {0, 2, 3}}, 4), "");  // unsorted
  EXPECT_EQ(triangulation_error({{0, 1, 2}, {0, 2, 3}}, 4), "");
}

TEST(NodeSplit, FanPairingHasTheLastPositionInEveryTriangle) {
  for (int k = 3; k <= 10; ++k) {
    const Pairing fan = fan_pairing(k);
    EXPECT_EQ(triangulation_error(fan, k), "") << "k = " << k;
    for (const NodeTriangle& t : fan) EXPECT_TRUE(contains(t, k - 1)) << "k = " << k;
    // It is one of the pairings a node may choose from.
    const std::vector<Pairing> all = node_pairings(k);
    const std::set<NodeTriangle> fan_set(fan.begin(), fan.end());
    bool found = false;
    for (const Pairing& p : all) found = found || std::set<NodeTriangle>(p.begin(), p.end()) == fan_set;
    EXPECT_TRUE(found) << "k = " << k;
  }
}

TEST(NodeSplit, TrianglesAroundRunFromNextToPreviousThroughSharedEdges) {
  for (int k = 3; k <= 9; ++k) {
    for (const Pairing& pairing : node_pairings(k)) {
      for (int i = 0; i < k; ++i) {
        const std::vector<int> around = triangles_around(pairing, k, i);
        int expected = 0;
        for (const NodeTriangle& t : pairing) expected += contains(t, i) ? 1 : 0;
        ASSERT_EQ(static_cast<int>(around.size()), expected) << "k = " << k << " i = " << i;
        ASSERT_FALSE(around.empty());
        for (int t : around) EXPECT_TRUE(contains(pairing[static_cast<size_t>(t)], i));
        EXPECT_TRUE(contains(pairing[static_cast<size_t>(around.front())], (i + 1) % k)) << "k " << k << " i " << i;
        EXPECT_TRUE(contains(pairing[static_cast<size_t>(around.back())], (i + k - 1) % k)) << "k " << k << " i " << i;
        for (size_t s = 0; s + 1 < around.size(); ++s) {
          const NodeTriangle& a = pairing[static_cast<size_t>(around[s])];
          const NodeTriangle& b = pairing[static_cast<size_t>(around[s + 1])];
          int shared = 0;
          for (int p : a) shared += contains(b, p) ? 1 : 0;
          EXPECT_EQ(shared, 2) << "k " << k << " i " << i << ": consecutive triangles share the edge through i";
        }
      }
    }
  }
}

TEST(NodeSplit, TrianglesAroundOnAKnownPairing) {
  // Square 0..3 split by the diagonal 0-2: position 0 meets (0,1,2) then (0,2,3).
  const Pairing p = {{0, 2, 3}, {0, 1, 2}};
  EXPECT_EQ(triangles_around(p, 4, 0), (std::vector<int>{1, 0}));
  EXPECT_EQ(triangles_around(p, 4, 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(triangles_around(p, 4, 1), (std::vector<int>{1}));
}

}  // namespace
}  // namespace ff
