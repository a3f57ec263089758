// Walker/Vose alias table: O(1) draws from a fixed discrete distribution.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/mcmc/rng.h"

namespace ksmc::runtime::mcmc {

class AliasTable {
 public:
  AliasTable() = default;
  // `weights` must be non-negative, finite, with a positive sum (checked by the caller,
  // Schedule); they are normalised here. Zero-weight entries are never drawn.
  explicit AliasTable(const std::vector<double>& weights);

  // Draws an index with one 64-bit random number: the high bits choose the column, the
  // low 53 bits the coin (n is small, so the two parts are independent enough).
  std::size_t sample(Rng& rng) const noexcept {
    const std::uint64_t r = rng.next();
    const std::size_t col = static_cast<std::size_t>(
        (static_cast<Uint128>(r) * static_cast<std::uint64_t>(prob_.size())) >> 64);
    const double coin = static_cast<double>(r & ((std::uint64_t{1} << 53) - 1)) * 0x1.0p-53;
    return coin < prob_[col] ? col : alias_[col];
  }
  std::size_t size() const noexcept { return prob_.size(); }

 private:
  std::vector<double> prob_;
  std::vector<std::size_t> alias_;
};

}  // namespace ksmc::runtime::mcmc
