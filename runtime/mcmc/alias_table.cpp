#include "runtime/mcmc/alias_table.h"

#include <numeric>

namespace ksmc::runtime::mcmc {

AliasTable::AliasTable(const std::vector<double>& weights)
    : prob_(weights.size(), 1.0), alias_(weights.size()) {
  const std::size_t n = weights.size();
  if (n == 0) return;
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<double> scaled(n);
  std::vector<std::size_t> small;
  std::vector<std::size_t> large;
  for (std::size_t i = 0; i < n; ++i) {
    alias_[i] = i;
    scaled[i] = weights[i] * static_cast<double>(n) / total;
    (scaled[i] < 1.0 ? small : large).push_back(i);
  }
  // Processed in index order (stacks filled in index order): deterministic tables.
  while (!small.empty() && !large.empty()) {
    const std::size_t s = small.back();
    small.pop_back();
    const std::size_t l = large.back();
    prob_[s] = scaled[s];
    alias_[s] = l;
    scaled[l] = (scaled[l] + scaled[s]) - 1.0;
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // Leftovers are 1 up to rounding; a zero-weight entry must never keep its own column.
  for (const std::size_t i : large) prob_[i] = 1.0;
  for (const std::size_t i : small) prob_[i] = weights[i] > 0.0 ? 1.0 : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] <= 0.0) prob_[i] = 0.0;
    if (prob_[i] < 1.0 && weights[alias_[i]] <= 0.0) {
      // Only reachable through rounding at the very end; redirect to a positive entry.
      for (std::size_t j = 0; j < n; ++j) {
        if (weights[j] > 0.0) {
          alias_[i] = j;
          break;
        }
      }
    }
  }
}

}  // namespace ksmc::runtime::mcmc
