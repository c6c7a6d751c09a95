#pragma once
// A 4-ary min-heap for the floods (clustering, seeding): half the levels of a binary heap and
// the four children on one cache line. `Less` must be a strict total order over the entries
// that are in the heap together (e.g. (cost, face) where a face is pushed again only at a
// lower cost): then any exact heap pops the same sequence, so results do not depend on it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace ff {

// Popping is what a flood of a million faces spends its time on.
template <typename T, typename Less>
class QuadHeap {
 public:
  explicit QuadHeap(Less before = Less()) : before_(before) {}
  bool empty() const { return items_.empty(); }
  size_t size() const { return items_.size(); }
  const T& at(size_t i) const { return items_[i]; }
  const T& top() const { return items_.front(); }
  void reserve(size_t n) { items_.reserve(n); }
  void push(T e) {
    size_t i = items_.size();
    items_.push_back(e);
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!before_(e, items_[parent])) break;
      items_[i] = items_[parent];
      i = parent;
    }
    items_[i] = e;
  }
  // Bottom-up: the hole walks down along the smaller children to a leaf (3 comparisons a
  // level, as a pairwise tournament), then the last entry, which belongs near the bottom,
  // sifts up from there; a top-down sift would also compare it with every child pair.
  T pop() {
    const T top = items_.front();
    const T last = items_.back();
    items_.pop_back();
    const size_t n = items_.size();
    if (n == 0) return top;
    size_t i = 0;
    for (;;) {
      const size_t first = 4 * i + 1;
      size_t best;
      if (first + 4 <= n) {
        // Indices by arithmetic on the comparisons: the smaller child is a coin toss, which a
        // branch would mispredict half the time.
        const size_t a = first + static_cast<size_t>(before_(items_[first + 1], items_[first]));
        const size_t b = first + 2 + static_cast<size_t>(before_(items_[first + 3], items_[first + 2]));
        const size_t take_b = static_cast<size_t>(before_(items_[b], items_[a]));
        best = a + take_b * (b - a);
      } else if (first < n) {
        best = first;
        for (size_t k = first + 1; k < n; ++k) {
          if (before_(items_[k], items_[best])) best = k;
        }
      } else {
        break;
      }
      items_[i] = items_[best];
      i = best;
    }
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!before_(last, items_[parent])) break;
      items_[i] = items_[parent];
      i = parent;
    }
    items_[i] = last;
    return top;
  }

 private:
  Less before_;
  std::vector<T> items_;
};

// A double as an unsigned integer in the same order: finite values map monotonically
// (negative ones reversed, below the positive ones), and -0 becomes +0 first so that equal
// values give equal keys. Two integers compare without a branch: the floods spent much of
// their time in mispredicted branches of the (cost, face) comparisons that pick the heap's
// smaller child.
inline std::uint64_t order_key(double value) {
  const double v = value + 0.0;  // -0 + 0 = +0
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// The value order_key() was made from (+0 for -0).
inline double key_value(std::uint64_t key) {
  const std::uint64_t bits = key >> 63 ? key & ~(std::uint64_t{1} << 63) : ~key;
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// A heap entry ordered by (value, id): the order of comparing (value, id) pairs, so the pops
// come in the same sequence, decided without unpredictable branches.
struct KeyedItem {
  std::uint64_t key;  // order_key(value)
  int id;
};

struct KeyedBefore {
  // The key comparison as a value (no branch); equal keys, rare, take the one branch, which
  // is therefore predicted well. (Written as (key <) || (key == and id <) the compiler made
  // the unpredictable first part a branch.)
  bool operator()(const KeyedItem& a, const KeyedItem& b) const {
    bool before = a.key < b.key;
    if (__builtin_expect(a.key == b.key, 0)) before = a.id < b.id;
    return before;
  }
};

}  // namespace ff
