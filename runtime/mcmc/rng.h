// The sampler's random number generator: xoshiro256** seeded through splitmix64.
//
// Own generator (not std::mt19937_64 + std distributions) so that the same seed gives
// the same chain on every platform and standard library: the distributions below are
// defined here, bit for bit. Chain c of a run with seed s uses Rng::for_chain(s, c),
// i.e. the base stream advanced by c jumps of 2^128 draws: streams never overlap.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ksmc::runtime::mcmc {

// One step of splitmix64 (Steele, Lea, Flood 2014); used to expand a 64-bit seed.
constexpr std::uint64_t splitmix64_next(std::uint64_t& state) noexcept {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

__extension__ typedef unsigned __int128 Uint128;  // GCC/Clang extension, for uniform_int

class Rng {
 public:
  using result_type = std::uint64_t;  // UniformRandomBitGenerator, usable with <random>

  explicit Rng(std::uint64_t seed = 0) noexcept {
    std::uint64_t sm = seed;
    for (auto& w : s_) w = splitmix64_next(sm);
  }

  // Stream of chain `chain` for run seed `seed`: independent of how many chains run.
  static Rng for_chain(std::uint64_t seed, std::uint64_t chain) noexcept {
    Rng r(seed);
    for (std::uint64_t c = 0; c < chain; ++c) r.jump();
    return r;
  }

  static constexpr result_type min() noexcept { return 0; }
  static constexpr result_type max() noexcept { return std::numeric_limits<result_type>::max(); }

  result_type operator()() noexcept { return next(); }

  std::uint64_t next() noexcept {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1), 53 random bits.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Uniform in (0, 1]: safe to take the log of.
  double uniform_pos() noexcept { return static_cast<double>((next() >> 11) + 1) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }

  // Uniform integer in [0, n), unbiased (Lemire's multiply-and-reject). n must be > 0.
  std::uint64_t uniform_int(std::uint64_t n) noexcept {
    Uint128 m = static_cast<Uint128>(next()) * n;
    auto low = static_cast<std::uint64_t>(m);
    if (low < n) {
      const std::uint64_t threshold = (0 - n) % n;
      while (low < threshold) {
        m = static_cast<Uint128>(next()) * n;
        low = static_cast<std::uint64_t>(m);
      }
    }
    return static_cast<std::uint64_t>(m >> 64);
  }

  bool bernoulli(double p) noexcept { return uniform() < p; }

  // Standard normal by Box–Muller (one value per call, no hidden cache: the state is
  // exactly the four words, so copies of an Rng replay identically).
  double normal() noexcept {
    const double u1 = uniform_pos();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586476925 * u2);
  }
  double normal(double mean, double sd) noexcept { return mean + sd * normal(); }

  // Advances the stream by 2^128 draws.
  void jump() noexcept {
    constexpr std::array<std::uint64_t, 4> kJump = {0x180EC6D33CFD0ABAULL, 0xD5A61266F0C9392CULL,
                                                    0xA9582618E03FC9AAULL, 0x39ABDC4529B1661CULL};
    std::array<std::uint64_t, 4> acc{};
    for (const std::uint64_t word : kJump) {
      for (int b = 0; b < 64; ++b) {
        if ((word & (std::uint64_t{1} << b)) != 0) {
          for (int i = 0; i < 4; ++i) acc[i] ^= s_[i];
        }
        next();
      }
    }
    s_ = acc;
  }

  const std::array<std::uint64_t, 4>& state() const noexcept { return s_; }
  friend bool operator==(const Rng&, const Rng&) = default;

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) noexcept {
    return (x << k) | (x >> (64 - k));
  }
  std::array<std::uint64_t, 4> s_{};
};

}  // namespace ksmc::runtime::mcmc
