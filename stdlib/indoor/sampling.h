// Drawing one element by its weight (seed eq. 3.15-3.17: normalise, accumulate, take the first
// index whose cumulative weight reaches a uniform number) and the log of its normalised weight.
#pragma once

#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <span>

namespace ksmc::stdlib::indoor {

using Rng = std::mt19937_64;

inline constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// log(w[i] / sum(w)); -inf when w[i] is 0 or the sum is not positive.
inline double log_normalized(std::span<const double> w, std::size_t i) {
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  if (!(total > 0.0) || i >= w.size() || !(w[i] > 0.0)) return kNegInf;
  return std::log(w[i] / total);
}

// Index drawn with probability w[i] / sum(w); nullopt when no weight is positive.
inline std::optional<std::size_t> draw_weighted(std::span<const double> w, Rng& rng) {
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  if (!(total > 0.0) || !std::isfinite(total)) return std::nullopt;
  const double k = std::uniform_real_distribution<double>(0.0, 1.0)(rng) * total;
  double acc = 0.0;
  std::size_t last = w.size();
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(w[i] > 0.0)) continue;
    acc += w[i];
    last = i;
    if (k < acc) return i;
  }
  return last;  // rounding at the top end
}

// Capped inverse weight (eq. 3.21, 3.22, 3.28): min(1 / omega, h); h when omega is 0.
inline double capped_inverse(double omega, double h) {
  return (omega > 0.0 && 1.0 / omega <= h) ? 1.0 / omega : h;
}

}  // namespace ksmc::stdlib::indoor
