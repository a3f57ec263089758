// The Metropolis–Hastings engine: runs one or several independent chains of a model
// under a kernel schedule. See model.h for the per-iteration protocol.
//
// Reproducibility: chain c draws from Rng::for_chain(seed, c) and shares nothing with
// the other chains, and results are merged in chain order, so the same seed gives the
// same RunResult whatever the number of threads or their timing (unless cancelled).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "runtime/mcmc/model.h"
#include "runtime/mcmc/plateau.h"
#include "runtime/mcmc/results.h"
#include "runtime/mcmc/schedule.h"

namespace ksmc::runtime::mcmc {

// Aggregate progress over all chains, reported on the thread that called Engine::run.
struct Progress {
  std::uint64_t iterations_done = 0;   // summed over chains
  std::uint64_t iterations_total = 0;  // iterations * chains
  double current_log_posterior = 0.0;  // chain 0's current state
  double best_log_posterior = 0.0;     // over chains
  double acceptance_rate = 0.0;        // accepted / selected, all chains
  double seconds = 0.0;
  bool finished = false;               // the last call of a run
  bool until_plateau = false;          // EngineConfig::stop_at_plateau: iterations_total is a cap
};

// Called on a chain's thread for every thinned iteration after burn-in (whether or not
// the sample is stored), with the chain's current (accepted) model.
using SampleObserver = std::function<void(unsigned chain, std::uint64_t iteration, const Model&)>;

struct EngineConfig {
  std::uint64_t iterations = 10000;  // per chain
  std::uint64_t seed = 1;
  unsigned chains = 1;
  unsigned threads = 0;          // 0 = min(chains, hardware threads)
  std::uint64_t burn_in = 0;     // samples are taken once more than burn_in iterations are done
  std::uint64_t samples = 0;     // posterior samples stored per chain (at most)
  std::uint64_t thin = 1;        // one sample every `thin` iterations after burn-in
  std::uint64_t trace_every = 0; // 0 = no trace
  const std::atomic<bool>* cancel = nullptr;  // set -> chains stop before their next iteration
  std::function<void(const Progress&)> progress;  // optional
  double progress_interval_s = 0.1;               // at most 10 calls per second by default
  SampleObserver observer;                        // optional
  // Stops each chain at its plateau (plateau.h), judged every `plateau_every` iterations on
  // the chain's best log posterior; `iterations` is then the most a chain runs. The decision
  // depends on the chain's own iterations and values only, so the run stays reproducible.
  std::optional<PlateauCriterion> stop_at_plateau;
  std::uint64_t plateau_every = 100;
  // Stored samples: the first `samples` after burn-in, or with keep_last_samples the last
  // ones (for a run whose length is not known in advance: stop_at_plateau).
  bool keep_last_samples = false;
};

class Engine {
 public:
  // The kernels must be in the same order, with the same names, as schedule.kernels().
  // Throws std::invalid_argument otherwise.
  Engine(ModelFactory factory, KernelList kernels, Schedule schedule);

  // Runs config.chains chains. Exceptions from the model or a kernel stop all chains and
  // are rethrown (as std::runtime_error "chain N: ...", lowest chain first).
  RunResult run(const EngineConfig& config) const;

  const Schedule& schedule() const noexcept { return schedule_; }
  const KernelList& kernels() const noexcept { return kernels_; }

  struct Monitor;  // live per-chain counters for progress reports (engine.cpp)

 private:
  ChainResult run_chain(unsigned chain, const EngineConfig& config, Monitor& monitor,
                        const std::atomic<bool>& abort) const;

  ModelFactory factory_;
  KernelList kernels_;
  Schedule schedule_;
};

// KernelInfo list (name, reverse) of a kernel table, to build a Schedule from.
std::vector<KernelInfo> kernel_infos(const KernelList& kernels);

}  // namespace ksmc::runtime::mcmc
