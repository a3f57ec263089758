#include "stdlib/indoor/detect/sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor::detect {

CumulativeSampler::CumulativeSampler(const std::vector<double>& weights) : weights_(weights) {
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const double w = weights_[i];
    if (!std::isfinite(w) || w < 0.0)
      throw std::invalid_argument("CumulativeSampler: weight " + std::to_string(i) + " is " + std::to_string(w) +
                                  " (must be finite and >= 0)");
    total_ += w;
  }
  cumulative_.resize(weights_.size());
  double acc = 0.0;
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    acc += weights_[i];
    cumulative_[i] = total_ > 0.0 ? acc / total_ : 0.0;
  }
  // Guard against rounding: the last non-zero candidate closes the distribution at 1.
  if (total_ > 0.0)
    for (std::size_t i = weights_.size(); i-- > 0;) {
      cumulative_[i] = 1.0;
      if (weights_[i] > 0.0) break;
    }
}

double CumulativeSampler::probability(std::size_t i) const {
  const double w = weights_.at(i);
  return total_ > 0.0 ? w / total_ : 0.0;
}

double CumulativeSampler::log_probability(std::size_t i) const {
  const double p = probability(i);
  return p > 0.0 ? std::log(p) : -std::numeric_limits<double>::infinity();
}

CumulativeSampler::Draw CumulativeSampler::draw(double k) const {
  if (empty()) throw std::logic_error("CumulativeSampler::draw: no candidate has a positive weight");
  if (!(k >= 0.0) || k >= 1.0) throw std::invalid_argument("CumulativeSampler::draw: k must be in [0, 1)");
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), k);
  std::size_t n = static_cast<std::size_t>(it - cumulative_.begin());
  if (n >= weights_.size()) n = weights_.size() - 1;  // unreachable: A_last == 1 > k
  return {n, probability(n)};
}

}  // namespace ksmc::stdlib::indoor::detect
