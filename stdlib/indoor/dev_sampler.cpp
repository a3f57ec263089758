#include "stdlib/indoor/dev_sampler.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ksmc::stdlib::indoor {

std::vector<ScheduleStage> schedule_table_3_2() {
  // Order: Add, Remove, Split, Merge, Shrink, Dilate, Allocate, Delete, Interchange.
  return {
      {1000, {0.8, 0.2, 0, 0, 0, 0, 0, 0, 0}},
      {4000, {0.05, 0.05, 0.15, 0.15, 0.15, 0.15, 0, 0, 0.3}},
      {std::numeric_limits<long long>::max(), {0.05, 0.05, 0.15, 0.15, 0.15, 0.15, 0.05, 0.05, 0.2}},
  };
}

DevSampler::DevSampler(ScoredWorld& state, const KernelSet& kernels, std::vector<ScheduleStage> schedule,
                       std::uint64_t seed)
    : state_(state), kernels_(kernels), schedule_(std::move(schedule)), rng_(seed),
      best_lp_(state.log_posterior()), best_(state.world()) {
  if (schedule_.empty()) throw std::invalid_argument("DevSampler: empty schedule");
  for (const auto& s : schedule_) {
    double t = 0.0;
    for (double p : s.phi) {
      if (!(p >= 0.0)) throw std::invalid_argument("DevSampler: negative selection probability");
      t += p;
    }
    if (!(t > 0.0)) throw std::invalid_argument("DevSampler: a schedule stage selects no kernel");
  }
}

const ScheduleStage& DevSampler::stage(long long beta) const {
  for (const auto& s : schedule_)
    if (beta <= s.until) return s;
  return schedule_.back();
}

bool DevSampler::step() {
  const long long beta = ++stats_.iterations;
  const ScheduleStage& st = stage(beta);
  const auto pick = draw_weighted(st.phi, rng_);
  const auto kind = static_cast<KernelKind>(*pick);
  const auto k = static_cast<std::size_t>(*pick);
  const auto p = kernels_.propose(kind, state_.world(), rng_);
  if (!p) {
    ++stats_.declined[k];
    return false;
  }
  ++stats_.proposed[k];
  const double phi_fwd = st.phi[k], phi_bwd = st.phi[static_cast<std::size_t>(reverse_of(kind))];
  if (!(phi_bwd > 0.0) || !std::isfinite(p->log_q_bwd)) return false;
  const double lp0 = state_.log_posterior();
  state_.apply(p->move);
  const double lp1 = state_.log_posterior();
  const double log_a = lp1 - lp0 + p->log_q_bwd - p->log_q_fwd + std::log(phi_bwd) - std::log(phi_fwd);
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng_);
  if (log_a >= 0.0 || std::log(u) < log_a) {
    ++stats_.accepted[k];
    if (lp1 > best_lp_) {
      best_lp_ = lp1;
      best_ = state_.world();
    }
    return true;
  }
  state_.revert(p->move);
  return false;
}

void DevSampler::run(long long iterations) {
  for (long long i = 0; i < iterations; ++i) step();
}

}  // namespace ksmc::stdlib::indoor
