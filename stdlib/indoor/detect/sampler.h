// Cumulative-weight sampling of a candidate set (seed eq. 3.15-3.17): weights are
// normalised (3.15), accumulated (3.16) and a uniform k in [0, 1) selects
// n = min{ i | k < A_i } (3.17; strict so that zero-weight candidates are never drawn).
// Every draw also returns its probability, for the log Q terms of the MH ratio.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace ksmc::stdlib::indoor::detect {

class CumulativeSampler {
 public:
  struct Draw {
    std::size_t index = 0;
    double probability = 0.0;
  };

  CumulativeSampler() = default;
  // Throws std::invalid_argument on a negative, NaN or infinite weight.
  explicit CumulativeSampler(const std::vector<double>& weights);

  std::size_t size() const { return weights_.size(); }
  // True when nothing can be drawn (no candidates or all weights zero).
  bool empty() const { return !(total_ > 0.0); }
  double total() const { return total_; }
  double weight(std::size_t i) const { return weights_.at(i); }
  // Normalised weight w'_i (eq. 3.15); 0 for an empty sampler.
  double probability(std::size_t i) const;
  // log of probability(i); -infinity for a zero-probability candidate.
  double log_probability(std::size_t i) const;
  // Cumulative A_i (eq. 3.16), A_{size-1} == 1.
  double cumulative(std::size_t i) const { return cumulative_.at(i); }

  // Eq. 3.17 for a given k in [0, 1). Throws std::logic_error when empty().
  Draw draw(double k) const;

  // Draw with a 64-bit generator (e.g. std::mt19937_64 or the runtime's Rng): k is built
  // from the top 53 bits, so the same generator state gives the same index everywhere.
  template <class Rng>
  Draw sample(Rng& rng) const {
    static_assert(Rng::min() == 0 && Rng::max() == std::numeric_limits<std::uint64_t>::max(),
                  "CumulativeSampler::sample needs a full-range 64-bit generator");
    const double k = static_cast<double>(static_cast<std::uint64_t>(rng()) >> 11) * 0x1.0p-53;
    return draw(k);
  }

 private:
  std::vector<double> weights_;
  std::vector<double> cumulative_;
  double total_ = 0.0;
};

}  // namespace ksmc::stdlib::indoor::detect
