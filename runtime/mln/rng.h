// The engines' random numbers: the runtime's one generator (xoshiro256** seeded through
// splitmix64, runtime/mcmc/rng.h) plus the two draws the inference engines use. Every
// engine takes a seed and owns one, so results are reproducible bit for bit.
#pragma once

#include <cstdint>

#include "runtime/mcmc/rng.h"

namespace ksmc::runtime::mln {

class Rng : public mcmc::Rng {
 public:
  explicit Rng(std::uint64_t seed) : mcmc::Rng(seed) {}
  // Uniform integer in [0, n), n > 0 (multiply-shift on 32 bits; bias < n / 2^32, fast).
  std::uint32_t below(std::uint32_t n) {
    return static_cast<std::uint32_t>(((next() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
  }
  bool coin(double p) { return bernoulli(p); }
};

}  // namespace ksmc::runtime::mln
