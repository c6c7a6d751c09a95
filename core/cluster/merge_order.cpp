#include "core/cluster/merge_order.h"

#include <algorithm>

namespace ff {

namespace {

double merge_cost(const Metric& metric, const std::vector<ClusterMoments>& moments, const std::vector<double>& energy,
                  const std::vector<Proxy>& proxies, int a, int b) {
  ClusterMoments merged = moments[static_cast<size_t>(a)];
  merged.add(moments[static_cast<size_t>(b)]);
  const Proxy p = metric.fit(merged, proxies[static_cast<size_t>(a)]);
  return metric.energy(merged, p).total() - energy[static_cast<size_t>(a)] - energy[static_cast<size_t>(b)];
}

}  // namespace

bool MergeOrder::later(const Pending& x, const Pending& y) {
  if (x.key != y.key) return x.key > y.key;
  if (x.exact != y.exact) return x.exact;  // the bound first
  return x.a != y.a ? x.a > y.a : x.b > y.b;
}

MergeOrder::MergeOrder(const Metric& metric, const std::vector<std::pair<int, int>>& pairs,
                       const std::vector<ClusterMoments>& moments, const std::vector<double>& energy,
                       const std::vector<Proxy>& proxies)
    : metric_(metric), moments_(moments), energy_(energy), proxies_(proxies) {
  heap_.reserve(pairs.size());
  for (const auto& [a, b] : pairs) {
    ClusterMoments merged = moments[static_cast<size_t>(a)];
    merged.add(moments[static_cast<size_t>(b)]);
    // The same subtractions as the cost's, and rounding is monotone: bound <= union energy
    // gives bound - e_a - e_b <= cost.
    const double bound =
        metric.energy_lower_bound(merged) - energy[static_cast<size_t>(a)] - energy[static_cast<size_t>(b)];
    heap_.push_back({bound, false, a, b});
  }
  std::make_heap(heap_.begin(), heap_.end(), later);
}

const MergeCandidate* MergeOrder::at(size_t i) {
  while (sorted_.size() <= i && !heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    Pending top = heap_.back();
    heap_.pop_back();
    if (top.exact) {
      sorted_.push_back({top.key, top.a, top.b});
      continue;
    }
    top.key = merge_cost(metric_, moments_, energy_, proxies_, top.a, top.b);
    top.exact = true;
    ++fitted_;
    heap_.push_back(top);
    std::push_heap(heap_.begin(), heap_.end(), later);
  }
  return i < sorted_.size() ? &sorted_[i] : nullptr;
}

std::vector<MergeCandidate> all_merges_sorted(const Metric& metric, const std::vector<std::pair<int, int>>& pairs,
                                              const std::vector<ClusterMoments>& moments,
                                              const std::vector<double>& energy, const std::vector<Proxy>& proxies) {
  std::vector<MergeCandidate> out;
  for (const auto& [a, b] : pairs) out.push_back({merge_cost(metric, moments, energy, proxies, a, b), a, b});
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ff
