// QuadHeap: pops exactly the sorted order of what was pushed, interleaved pushes and pops
// included (the floods push while they pop), for every size up to past a few levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
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

}  // namespace
}  // namespace ff
