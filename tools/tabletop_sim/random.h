// Portable seeded random numbers for the scene generator.
// std::*_distribution algorithms differ between standard libraries, so the generator draws
// through this class only: same seed -> same numbers on every platform.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace ksmc::tools::tabletop_sim {

// SplitMix64 step: turns (seed, index) pairs into well-mixed independent seeds.
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi] (inclusive); lo <= hi.
  int uniform_int(int lo, int hi) {
    const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
    return lo + static_cast<int>(engine_() % span);  // span is tiny: bias below 1e-17
  }
  bool bernoulli(double p) { return uniform() < p; }
  // Box-Muller, one value per call (no cached state besides the engine).
  double normal(double mean, double sigma) {
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  // Index drawn proportionally to non-negative weights (at least one positive).
  template <typename Range>
  std::size_t weighted_index(const Range& weights) {
    double total = 0.0;
    for (double w : weights) total += w;
    double r = uniform() * total;
    std::size_t i = 0;
    std::size_t last_positive = 0;
    for (double w : weights) {
      if (w > 0.0) {
        last_positive = i;
        if (r < w) return i;
      }
      r -= w;
      ++i;
    }
    return last_positive;
  }
  std::uint64_t next_u64() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace ksmc::tools::tabletop_sim
