#include "core/mesh/weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace ff::detail {

namespace {

// SplitMix64's finaliser: every input bit affects every output bit.
std::uint64_t mix(std::uint64_t h) {
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

std::uint64_t position_hash(const Vec3& p) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int i = 0; i < 3; ++i) {
    const double c = p[i] + 0.0;  // -0.0 becomes 0.0: the same position
    std::uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    h = mix(h ^ bits);
  }
  return h;
}

// Coincident vertices have equal position hashes. A counting pass by the top hash bits
// splits the vertices into cache-sized partitions (each in index order); within one, a
// small open-addressing table finds the first vertex at each position. The outcome
// depends on positions and indices only (lowest index per position), never on the hash
// or probe order, which only decide speed. Much faster than a lexicographic sort of the
// positions, which dominated clean_mesh on large soups.
std::vector<int> weld_exact(const std::vector<Vec3>& positions, const std::vector<char>& weldable) {
  const size_t n = positions.size();
  std::vector<int> rep(n);
  std::vector<std::uint64_t> hash(n);
  size_t members = 0;
  for (size_t v = 0; v < n; ++v) {
    rep[v] = static_cast<int>(v);
    if (!weldable.empty() && !weldable[v]) continue;
    hash[v] = position_hash(positions[v]);
    ++members;
  }
  int bits = 0;
  // About 65 000 vertices per partition: few enough write streams for the scatter to
  // stay in cache, and a probe table that fits in L2 (measured best on 3M-vertex soups).
  while (bits < 16 && (members >> (bits + 16)) > 0) ++bits;
  const auto partition_of = [bits](std::uint64_t h) {
    return bits == 0 ? size_t{0} : static_cast<size_t>(h >> (64 - bits));
  };
  std::vector<size_t> start((size_t{1} << bits) + 1, 0);
  for (size_t v = 0; v < n; ++v) {
    if (weldable.empty() || weldable[v]) ++start[partition_of(hash[v]) + 1];
  }
  for (size_t p = 0; p + 1 < start.size(); ++p) start[p + 1] += start[p];
  // Per vertex: low 32 hash bits (to probe and to compare cheaply), its index and a copy
  // of its position, so a partition is resolved without reading all over `positions`.
  struct Entry {
    std::uint32_t hash;
    int vertex;
    double x, y, z;
  };
  std::vector<Entry> entries(members);
  {
    std::vector<size_t> cursor(start.begin(), start.end() - 1);
    for (size_t v = 0; v < n; ++v) {
      if (!weldable.empty() && !weldable[v]) continue;
      const Vec3& pos = positions[v];
      entries[cursor[partition_of(hash[v])]++] = {static_cast<std::uint32_t>(hash[v]), static_cast<int>(v), pos.x(),
                                                  pos.y(), pos.z()};
    }
  }

  std::vector<int> table;  // entry index within the partition, -1 when free
  for (size_t p = 0; p + 1 < start.size(); ++p) {
    const size_t size = start[p + 1] - start[p];
    if (size < 2) continue;
    size_t slots = 4;
    while (slots < 2 * size) slots <<= 1;
    table.assign(slots, -1);
    for (size_t k = start[p]; k < start[p + 1]; ++k) {
      const Entry& e = entries[k];
      for (size_t s = e.hash & (slots - 1);; s = (s + 1) & (slots - 1)) {
        if (table[s] < 0) {
          table[s] = static_cast<int>(k - start[p]);  // first (lowest-index) vertex here
          break;
        }
        const Entry& t = entries[start[p] + static_cast<size_t>(table[s])];
        if (t.hash == e.hash && t.x == e.x && t.y == e.y && t.z == e.z) {
          rep[static_cast<size_t>(e.vertex)] = t.vertex;
          break;
        }
      }
    }
  }
  return rep;
}

using Cell = std::array<std::int64_t, 3>;

// Cells of a grid, each with the list of representatives inside it (linked through
// `next`). Only looked up by key, never iterated, so its layout cannot affect results.
class CellLists {
 public:
  // Head of the cell's list, or -1.
  int head(const Cell& c) const {
    if (keys_.empty()) return -1;
    for (size_t s = slot_of(c);; s = (s + 1) & (slots_.size() - 1)) {
      if (slots_[s] < 0) return -1;
      if (same(keys_[static_cast<size_t>(slots_[s])], c)) return heads_[static_cast<size_t>(slots_[s])];
    }
  }
  void push(const Cell& c, int v, std::vector<int>& next) {
    if (2 * (keys_.size() + 1) > slots_.size()) grow();
    size_t s = slot_of(c);
    while (slots_[s] >= 0 && !same(keys_[static_cast<size_t>(slots_[s])], c)) {
      s = (s + 1) & (slots_.size() - 1);
    }
    if (slots_[s] < 0) {
      slots_[s] = static_cast<int>(keys_.size());
      keys_.push_back(c);
      heads_.push_back(-1);
    }
    int& head = heads_[static_cast<size_t>(slots_[s])];
    next[static_cast<size_t>(v)] = head;
    head = v;
  }

 private:
  static bool same(const Cell& a, const Cell& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
  size_t slot_of(const Cell& c) const {
    std::uint64_t h = 0;
    for (std::int64_t x : c) h = mix((h ^ static_cast<std::uint64_t>(x)) * 0x9e3779b97f4a7c15ull);
    return static_cast<size_t>(h) & (slots_.size() - 1);
  }
  void grow() {
    slots_.assign(std::max<size_t>(64, 2 * slots_.size()), -1);
    for (size_t k = 0; k < keys_.size(); ++k) {
      size_t s = slot_of(keys_[k]);
      while (slots_[s] >= 0) s = (s + 1) & (slots_.size() - 1);
      slots_[s] = static_cast<int>(k);
    }
  }
  std::vector<int> slots_;  // index into keys_ / heads_, -1 when free
  std::vector<Cell> keys_;
  std::vector<int> heads_;
};

// Visiting vertices in index order, each one looks for representatives in the grid
// cells that a ball of radius `margin` (the tolerance, a little more) around it can
// touch. Cells are 8 margins wide, so that is one cell per axis 3 times in 4, and never
// more than two. Two representatives are more than `tolerance` apart, so a cell holds a
// bounded number of them.
std::vector<int> weld_within(const std::vector<Vec3>& positions, double tolerance, const std::vector<char>& weldable) {
  const size_t n = positions.size();
  double largest = 0.0;
  for (const Vec3& p : positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  // Covers rounding in the distance and in the divisions below, also for a tolerance
  // below the coordinates' precision (which would otherwise ask for millions of cells).
  const double margin = tolerance * (1.0 + 1e-6) + largest * 1e-15;
  const double size = 8.0 * margin, tol2 = tolerance * tolerance;
  // Clamping only merges far-away cells (slower, still correct).
  static constexpr double kLimit = 4.0e18;
  const auto axis_cell = [size](double x) {
    return static_cast<std::int64_t>(std::clamp(std::floor(x / size), -kLimit, kLimit));
  };
  std::vector<int> rep(n), next(n, -1);
  CellLists cells;
  for (size_t v = 0; v < n; ++v) {
    rep[v] = static_cast<int>(v);
    if (!weldable.empty() && !weldable[v]) continue;
    const Vec3& p = positions[v];
    Cell lo, hi, own;
    for (size_t i = 0; i < 3; ++i) {
      lo[i] = axis_cell(p[static_cast<int>(i)] - margin);
      hi[i] = axis_cell(p[static_cast<int>(i)] + margin);
      own[i] = axis_cell(p[static_cast<int>(i)]);
    }
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          for (int r = cells.head({x, y, z}); r >= 0; r = next[static_cast<size_t>(r)]) {
            const double d2 = (positions[static_cast<size_t>(r)] - p).squaredNorm();
            if (d2 <= tol2 && (d2 < best_d2 || (d2 == best_d2 && r < best))) {
              best = r;
              best_d2 = d2;
            }
          }
        }
      }
    }
    if (best >= 0) {
      rep[v] = best;
    } else {
      cells.push(own, static_cast<int>(v), next);
    }
  }
  return rep;
}

}  // namespace

std::vector<int> weld_representatives(const std::vector<Vec3>& positions, double tolerance,
                                      const std::vector<char>& weldable) {
  const std::vector<int> exact = weld_exact(positions, weldable);
  if (tolerance == 0.0) return exact;
  // Coincident vertices always stay together, and the slower search only sees one
  // vertex per position (a soup has about six per position).
  std::vector<char> first_at_position(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    first_at_position[v] = (weldable.empty() || weldable[v]) && exact[v] == static_cast<int>(v);
  }
  const std::vector<int> within = weld_within(positions, tolerance, first_at_position);
  std::vector<int> rep(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) rep[v] = within[static_cast<size_t>(exact[v])];
  return rep;
}

}  // namespace ff::detail
