// What a Metropolis–Hastings run produces: per-kernel counts, traces, best state,
// posterior samples; per chain and merged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "runtime/mcmc/model.h"
#include "runtime/mcmc/plateau.h"

namespace ksmc::runtime::mcmc {

// Counts for one kernel. selected = declined + accepted + rejected_proposals; a declined
// proposal counts as a rejection, so acceptance_rate = accepted / selected.
struct KernelStats {
  std::string name;
  std::uint64_t selected = 0;
  std::uint64_t declined = 0;
  std::uint64_t accepted = 0;

  std::uint64_t proposed() const noexcept { return selected - declined; }
  std::uint64_t rejected() const noexcept { return selected - accepted; }
  double acceptance_rate() const noexcept {
    return selected == 0 ? 0.0 : static_cast<double>(accepted) / static_cast<double>(selected);
  }
  KernelStats& operator+=(const KernelStats& o) noexcept {
    selected += o.selected;
    declined += o.declined;
    accepted += o.accepted;
    return *this;
  }
  friend bool operator==(const KernelStats&, const KernelStats&) = default;
};

// One trace row, taken after `iteration` iterations (every trace_every, plus the last).
struct TracePoint {
  std::uint64_t iteration = 0;
  double log_posterior = 0.0;
  double log_likelihood = 0.0;
  double log_prior = 0.0;
  double best_log_posterior = 0.0;
  double acceptance_window = 0.0;  // accepted / selected since the previous trace row
  double acceptance_total = 0.0;   // accepted / selected since the start
  // Per kernel (kernel-table order): accepted / selected since the previous trace row,
  // NaN when the kernel was not selected in that window.
  std::vector<double> kernel_acceptance_window;
  friend bool operator==(const TracePoint& a, const TracePoint& b) {
    if (a.kernel_acceptance_window.size() != b.kernel_acceptance_window.size()) return false;
    for (std::size_t k = 0; k < a.kernel_acceptance_window.size(); ++k) {
      const double x = a.kernel_acceptance_window[k];
      const double y = b.kernel_acceptance_window[k];
      if (!(x == y || (x != x && y != y))) return false;  // NaN equals NaN here
    }
    return a.iteration == b.iteration && a.log_posterior == b.log_posterior &&
           a.log_likelihood == b.log_likelihood && a.log_prior == b.log_prior &&
           a.best_log_posterior == b.best_log_posterior && a.acceptance_window == b.acceptance_window &&
           a.acceptance_total == b.acceptance_total;
  }
};

struct PosteriorSample {
  std::uint64_t iteration = 0;  // iterations done when the sample was taken
  double log_posterior = 0.0;
  Snapshot state;
};

struct ChainResult {
  unsigned chain = 0;
  std::uint64_t iterations = 0;  // done (fewer than asked when cancelled)
  bool cancelled = false;
  double seconds = 0.0;
  double initial_log_posterior = 0.0;
  double final_log_posterior = 0.0;
  double best_log_posterior = 0.0;
  std::uint64_t best_iteration = 0;  // 0 = the initial state
  Snapshot best_state;
  std::vector<KernelStats> kernels;  // in kernel-table order
  std::vector<TracePoint> trace;
  std::vector<PosteriorSample> samples;
  // With EngineConfig::stop_at_plateau: where the chain's plateau began (iteration, best log
  // posterior, wall seconds); the chain stopped when it became known. nullopt: not reached.
  std::optional<PlateauPoint> plateau;

  std::uint64_t accepted() const noexcept;
};

struct RunResult {
  std::vector<ChainResult> chains;   // in chain order
  std::size_t best_chain = 0;        // highest best_log_posterior; ties: lowest index
  std::vector<KernelStats> kernels;  // summed over chains
  std::uint64_t iterations = 0;      // summed over chains
  double seconds = 0.0;              // wall clock of the whole run
  bool cancelled = false;

  const ChainResult& best() const { return chains.at(best_chain); }
  double acceptance_rate() const noexcept;
};

}  // namespace ksmc::runtime::mcmc
