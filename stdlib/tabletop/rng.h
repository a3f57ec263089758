// Portable random draws on top of std::mt19937_64 (whose output sequence the standard
// fixes), so a seed gives the same proposals with every standard library —
// std::normal_distribution's algorithm is implementation-defined.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace ksmc::stdlib::tabletop {

// Uniform in (0, 1): 53 random bits, never exactly 0.
inline double uniform_open01(std::mt19937_64& rng) {
  const std::uint64_t bits = rng() >> 11;
  return (static_cast<double>(bits) + 0.5) * (1.0 / 9007199254740992.0);
}

// Standard normal by Box–Muller (two uniforms per draw).
inline double standard_normal(std::mt19937_64& rng) {
  const double u1 = uniform_open01(rng);
  const double u2 = uniform_open01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace ksmc::stdlib::tabletop
