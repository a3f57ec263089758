// A plain Metropolis-Hastings loop over the indoor kernels (eq. 3.9) with an iteration-staged
// schedule Phi (Table 3.2). For development tests and benchmarks only; the production sampler is
// the engine in runtime/mcmc, which a later adapter wires to ScoredWorld and KernelSet.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "stdlib/indoor/kernels.h"
#include "stdlib/indoor/scored_world.h"

namespace ksmc::stdlib::indoor {

struct ScheduleStage {
  long long until = 0;                      // applies to iterations beta <= until (1-based)
  std::array<double, kKernelKinds> phi{};   // selection probability per KernelKind
};

// Table 3.2 of the seed (iterations <= 1000, <= 4000, beyond).
std::vector<ScheduleStage> schedule_table_3_2();

struct SamplerStats {
  std::array<long long, kKernelKinds> proposed{}, accepted{}, declined{};
  long long iterations = 0;
};

class DevSampler {
 public:
  DevSampler(ScoredWorld& state, const KernelSet& kernels, std::vector<ScheduleStage> schedule,
             std::uint64_t seed);
  // One MH iteration; returns true when a move was accepted.
  bool step();
  void run(long long iterations);

  const SamplerStats& stats() const { return stats_; }
  double best_log_posterior() const { return best_lp_; }
  const World& best_world() const { return best_; }

 private:
  const ScheduleStage& stage(long long beta) const;

  ScoredWorld& state_;
  const KernelSet& kernels_;
  std::vector<ScheduleStage> schedule_;
  Rng rng_;
  SamplerStats stats_;
  double best_lp_;
  World best_;
};

}  // namespace ksmc::stdlib::indoor
