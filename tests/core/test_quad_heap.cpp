// QuadHeap: pops exactly the sorted order of what was pushed, interleaved pushes and pops
// included (the floods push while they pop), for every size up to past a few levels; the
// floods' branch-free keys (order_key, KeyedItem) order as the doubles and pairs they stand for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "core/cluster/quad_heap.h"
#include "core/util/random.h"

namespace ff {
namespace {

using Item = std::pair<double, int>;

TEST(QuadHeap, PopsInSortedOrderWhilePushing) {
  SplitMix64 rng(7);
  for (int n : {0, 1, 2, 3, 4, 5, 6, 17, 21, 85, 86, 341, 1000}) {
    QuadHeap<Item, std::less<Item>> heap;
    std::vector<Item> reference;  // what is in the heap, kept sorted descending (min at the back)
    std::vector<Item> popped, expected;
    int pushed = 0;
    while (pushed < n || !heap.empty()) {
      // Push in bursts, pop in between: costs repeat (ties broken by the second member).
      const bool push = pushed < n && (heap.empty() || rng.uniform() < 0.6);
      if (push) {
        const Item item{static_cast<double>(static_cast<int>(rng.uniform() * 20.0)), pushed++};
        heap.push(item);
        reference.push_back(item);
        std::sort(reference.begin(), reference.end(), std::greater<Item>());
        ASSERT_EQ(heap.top(), reference.back());
      } else {
        popped.push_back(heap.pop());
        expected.push_back(reference.back());
        reference.pop_back();
      }
      ASSERT_EQ(heap.size(), reference.size());
    }
    EXPECT_EQ(popped, expected) << "n=" << n;
    EXPECT_EQ(static_cast<int>(popped.size()), n);
  }
}

// order_key: the order of the doubles, equal keys exactly for equal values (-0 and +0 too),
// and key_value gives the value back.
TEST(QuadHeap, OrderKeysKeepTheOrderOfDoubles) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> values = {-inf, -std::numeric_limits<double>::max(), -1e300, -2.5, -1.0,
                                      -std::numeric_limits<double>::denorm_min(), -0.0, 0.0,
                                      std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                                      1e-300, 0.1, 1.0, 1.0 + 1e-16, 1.0 + 2.3e-16, 3.0, 1e300,
                                      std::numeric_limits<double>::max(), inf};
  for (double a : values) {
    EXPECT_EQ(key_value(order_key(a)), a);
    for (double b : values) {
      EXPECT_EQ(order_key(a) < order_key(b), a < b) << a << " " << b;
      EXPECT_EQ(order_key(a) == order_key(b), a == b) << a << " " << b;
    }
  }
  EXPECT_FALSE(std::signbit(key_value(order_key(-0.0))));
}

// A heap of KeyedItem pops what a heap of (value, id) pairs pops, ties and negative values
// included.
TEST(QuadHeap, KeyedItemsPopAsPairs) {
  SplitMix64 rng(11);
  QuadHeap<Item, std::less<Item>> pairs;
  QuadHeap<KeyedItem, KeyedBefore> keyed;
  for (int i = 0; i < 2000; ++i) {
    const double value = static_cast<double>(static_cast<int>(rng.uniform() * 40.0) - 10) * 0.25;
    const int id = static_cast<int>(rng.uniform() * 500.0);
    pairs.push({value, id});
    keyed.push({order_key(value), id});
    if (rng.uniform() < 0.3) {
      const Item p = pairs.pop();
      const KeyedItem k = keyed.pop();
      ASSERT_EQ(p.first, key_value(k.key));
      ASSERT_EQ(p.second, k.id);
    }
  }
  while (!pairs.empty()) {
    const Item p = pairs.pop();
    const KeyedItem k = keyed.pop();
    ASSERT_EQ(p.first, key_value(k.key));
    ASSERT_EQ(p.second, k.id);
  }
  EXPECT_TRUE(keyed.empty());
}

}  // namespace
}  // namespace ff
