#include "runtime/mcmc/plateau.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ksmc::runtime::mcmc {

PlateauDetector::PlateauDetector(PlateauCriterion c) : c_(c) {
  if (c_.window == 0) throw std::invalid_argument("PlateauDetector: window must be at least 1 iteration");
  if (!std::isfinite(c_.min_gain) || c_.min_gain < 0.0)
    throw std::invalid_argument("PlateauDetector: min_gain must be finite and >= 0, got " + std::to_string(c_.min_gain));
}

bool PlateauDetector::observe(std::uint64_t iteration, double best, double seconds) {
  if (last_ && iteration <= last_->iteration)
    throw std::invalid_argument("PlateauDetector: iteration " + std::to_string(iteration) + " after " +
                                std::to_string(last_->iteration));
  if (last_ && best < last_->best)
    throw std::invalid_argument("PlateauDetector: best log posterior decreased at iteration " + std::to_string(iteration));
  last_ = PlateauPoint{iteration, best, seconds};
  if (plateau_) return true;
  pending_.push_back(*last_);
  // Judge every pending point i that this point is the first to reach i + window for.
  while (!pending_.empty() && pending_.front().iteration + c_.window <= iteration) {
    if (best - pending_.front().best <= c_.min_gain) {
      plateau_ = pending_.front();
      detected_ = last_;
      pending_.clear();
      return true;
    }
    pending_.pop_front();
  }
  return false;
}

}  // namespace ksmc::runtime::mcmc
