#include "runtime/mcmc/engine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "runtime/io/cancel.h"

namespace ksmc::runtime::mcmc {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// How often (in iterations) a chain publishes its counters for progress reports.
constexpr std::uint64_t kPublishEvery = 256;

}  // namespace

// Per-chain live counters, written by the chain (relaxed), read by the reporting thread.
struct Engine::Monitor {
  struct Chain {
    std::atomic<std::uint64_t> done{0};
    std::atomic<std::uint64_t> selected{0};
    std::atomic<std::uint64_t> accepted{0};
    std::atomic<double> current{kNegInf};
    std::atomic<double> best{kNegInf};
  };
  explicit Monitor(unsigned n) : chains(n) {}
  std::vector<Chain> chains;
  std::mutex mutex;
  std::condition_variable cv;
  unsigned finished = 0;  // guarded by mutex
};

std::vector<KernelInfo> kernel_infos(const KernelList& kernels) {
  std::vector<KernelInfo> infos;
  infos.reserve(kernels.size());
  for (const auto& k : kernels) {
    if (!k) throw std::invalid_argument("kernel list contains a null kernel");
    infos.push_back(KernelInfo{std::string(k->name()), std::string(k->reverse_name())});
  }
  return infos;
}

Engine::Engine(ModelFactory factory, KernelList kernels, Schedule schedule)
    : factory_(std::move(factory)), kernels_(std::move(kernels)), schedule_(std::move(schedule)) {
  if (!factory_) throw std::invalid_argument("engine: no model factory");
  const auto infos = kernel_infos(kernels_);
  if (infos.empty() || schedule_.row_count() == 0) {
    throw std::invalid_argument("engine: no kernels or an empty schedule");
  }
  if (infos.size() != schedule_.kernel_count()) {
    throw std::invalid_argument(fmt::format("engine: {} kernels but the schedule has {}",
                                            infos.size(), schedule_.kernel_count()));
  }
  for (std::size_t k = 0; k < infos.size(); ++k) {
    const KernelInfo& s = schedule_.kernels()[k];
    if (infos[k].name != s.name || infos[k].reverse != s.reverse) {
      throw std::invalid_argument(fmt::format(
          "engine: kernel {} is '{}' (reverse '{}') but the schedule expects '{}' (reverse '{}')", k,
          infos[k].name, infos[k].reverse, s.name, s.reverse));
    }
  }
}

ChainResult Engine::run_chain(unsigned chain, const EngineConfig& cfg, Monitor& monitor,
                              const std::atomic<bool>& abort) const {
  const auto start = Clock::now();
  Monitor::Chain& live = monitor.chains[chain];
  Rng rng = Rng::for_chain(cfg.seed, chain);
  std::unique_ptr<Model> model = factory_(chain);
  if (!model) throw std::runtime_error("model factory returned no model");

  ChainResult res;
  res.chain = chain;
  res.kernels.resize(kernels_.size());
  for (std::size_t k = 0; k < kernels_.size(); ++k) res.kernels[k].name = kernels_[k]->name();

  double ll = model->log_likelihood();
  double lprior = model->log_prior();
  double lp = ll + lprior;
  if (std::isnan(lp)) throw std::runtime_error("the initial state has a NaN log posterior");
  res.initial_log_posterior = lp;
  res.best_log_posterior = lp;
  res.best_state = model->snapshot();

  const std::uint64_t thin = std::max<std::uint64_t>(cfg.thin, 1);
  std::size_t row = schedule_.row_index(0);
  std::uint64_t row_end = schedule_.row_end(row);
  std::uint64_t selected_total = 0;
  std::uint64_t accepted_total = 0;
  std::uint64_t window_selected = 0;
  std::uint64_t window_accepted = 0;
  std::uint64_t done = 0;
  std::vector<KernelStats> at_last_trace = res.kernels;

  auto push_trace = [&] {
    TracePoint t;
    t.iteration = done;
    t.log_posterior = lp;
    t.log_likelihood = ll;
    t.log_prior = lprior;
    t.best_log_posterior = res.best_log_posterior;
    t.acceptance_window = window_selected == 0 ? 0.0
                                               : static_cast<double>(window_accepted) /
                                                     static_cast<double>(window_selected);
    t.acceptance_total = selected_total == 0 ? 0.0
                                             : static_cast<double>(accepted_total) /
                                                   static_cast<double>(selected_total);
    t.kernel_acceptance_window.resize(res.kernels.size());
    for (std::size_t k = 0; k < res.kernels.size(); ++k) {
      const std::uint64_t sel = res.kernels[k].selected - at_last_trace[k].selected;
      const std::uint64_t acc = res.kernels[k].accepted - at_last_trace[k].accepted;
      t.kernel_acceptance_window[k] = sel == 0 ? std::numeric_limits<double>::quiet_NaN()
                                               : static_cast<double>(acc) / static_cast<double>(sel);
      at_last_trace[k] = res.kernels[k];
    }
    res.trace.push_back(t);
    window_selected = 0;
    window_accepted = 0;
  };
  auto publish = [&] {
    live.done.store(done, std::memory_order_relaxed);
    live.selected.store(selected_total, std::memory_order_relaxed);
    live.accepted.store(accepted_total, std::memory_order_relaxed);
    live.current.store(lp, std::memory_order_relaxed);
    live.best.store(res.best_log_posterior, std::memory_order_relaxed);
  };
  publish();

  std::vector<const Kernel*> kernels(kernels_.size());
  for (std::size_t k = 0; k < kernels_.size(); ++k) kernels[k] = kernels_[k].get();

  // While sampling, a cancellation request stops the chain between iterations (below), never
  // inside one: polls in the model's own computations (grounding, inference, evidence) are
  // shielded, so a signal cannot abandon a half-made proposal and lose the run's state.
  const io::CancelShield between_iterations_only;
  std::optional<PlateauDetector> plateau;
  if (cfg.stop_at_plateau) plateau.emplace(*cfg.stop_at_plateau);
  const std::uint64_t plateau_every = std::max<std::uint64_t>(cfg.plateau_every, 1);
  std::size_t next_sample = 0;  // keep_last_samples: the slot the next sample overwrites
  while (done < cfg.iterations) {
    if ((cfg.cancel != nullptr && cfg.cancel->load(std::memory_order_relaxed)) ||
        abort.load(std::memory_order_relaxed)) {
      res.cancelled = true;
      break;
    }
    if (done >= row_end) {
      row = schedule_.row_index(done);
      row_end = schedule_.row_end(row);
    }
    const std::size_t k = schedule_.pick(row, rng);
    KernelStats& stats = res.kernels[k];
    ++stats.selected;
    ++selected_total;
    ++window_selected;
    const Proposal p = kernels[k]->propose(*model, rng);
    if (p.was_declined()) {
      ++stats.declined;
    } else {
      if (std::isnan(p.log_q_fwd) || std::isnan(p.log_q_bwd) || std::isnan(p.log_screened)) {
        model->reject();
        throw std::runtime_error(fmt::format("kernel '{}' returned a NaN proposal density at iteration {}",
                                             kernels[k]->name(), done));
      }
      const double new_ll = model->log_likelihood();
      const double new_prior = model->log_prior();
      const double new_lp = new_ll + new_prior;
      bool accept = false;
      if (!(new_lp > kNegInf)) {
        accept = false;  // impossible (or NaN) state
      } else if (!(lp > kNegInf)) {
        accept = true;   // leaving an impossible initial state
      } else {
        // The change of each term, not of their sums: a constant in the prior (rules whose
        // evidence is the same in every state) then cancels exactly, and cannot move the chain
        // by rounding, which at log_alpha = 0 decides whether a uniform is drawn.
        const double log_alpha = ((new_ll - ll) + (new_prior - lprior)) + (p.log_q_bwd - p.log_q_fwd) +
                                 schedule_.log_selection_ratio(row, k) - p.log_screened;
        accept = log_alpha >= 0.0 || std::log(rng.uniform_pos()) < log_alpha;
      }
      if (accept) {
        model->accept();
        ll = new_ll;
        lprior = new_prior;
        lp = new_lp;
        ++stats.accepted;
        ++accepted_total;
        ++window_accepted;
        if (lp > res.best_log_posterior) {
          res.best_log_posterior = lp;
          res.best_iteration = done + 1;
          res.best_state = model->snapshot();
        }
      } else {
        model->reject();
      }
    }
    ++done;
    if (cfg.trace_every != 0 && done % cfg.trace_every == 0) push_trace();
    if (done > cfg.burn_in && (done - cfg.burn_in) % thin == 0) {
      if (res.samples.size() < cfg.samples) {
        res.samples.push_back(PosteriorSample{done, lp, model->snapshot()});
      } else if (cfg.keep_last_samples && cfg.samples != 0) {
        res.samples[next_sample] = PosteriorSample{done, lp, model->snapshot()};
        next_sample = (next_sample + 1) % res.samples.size();
      }
      if (cfg.observer) cfg.observer(chain, done, *model);
    }
    if (done % kPublishEvery == 0) publish();
    if (plateau && done % plateau_every == 0 &&
        plateau->observe(done, res.best_log_posterior, seconds_since(start))) {
      res.plateau = plateau->plateau();
      break;
    }
  }
  // The ring of the last samples, oldest first.
  std::rotate(res.samples.begin(), res.samples.begin() + static_cast<std::ptrdiff_t>(next_sample), res.samples.end());
  if (cfg.trace_every != 0 && (res.trace.empty() || res.trace.back().iteration != done)) push_trace();
  res.iterations = done;
  res.final_log_posterior = lp;
  res.seconds = seconds_since(start);
  publish();
  return res;
}

RunResult Engine::run(const EngineConfig& cfg) const {
  if (cfg.chains == 0) throw std::invalid_argument("engine: chains must be at least 1");
  if (cfg.stop_at_plateau) (void)PlateauDetector(*cfg.stop_at_plateau);  // checks the criterion
  const auto start = Clock::now();
  const unsigned n = cfg.chains;
  unsigned workers = cfg.threads != 0 ? cfg.threads : std::max(1U, std::thread::hardware_concurrency());
  workers = std::min(workers, n);

  Monitor monitor(n);
  std::vector<ChainResult> results(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<unsigned> next{0};
  std::atomic<bool> abort{false};

  auto worker = [&] {
    for (unsigned c = next.fetch_add(1); c < n; c = next.fetch_add(1)) {
      try {
        results[c] = run_chain(c, cfg, monitor, abort);
      } catch (...) {
        errors[c] = std::current_exception();
        abort.store(true);
      }
      std::lock_guard<std::mutex> lock(monitor.mutex);
      ++monitor.finished;
      monitor.cv.notify_all();
    }
  };

  auto report = [&](bool finished) {
    if (!cfg.progress) return;
    Progress p;
    p.iterations_total = cfg.iterations * n;
    p.until_plateau = cfg.stop_at_plateau.has_value();
    p.best_log_posterior = kNegInf;
    std::uint64_t selected = 0;
    std::uint64_t accepted = 0;
    for (auto& c : monitor.chains) {
      p.iterations_done += c.done.load(std::memory_order_relaxed);
      selected += c.selected.load(std::memory_order_relaxed);
      accepted += c.accepted.load(std::memory_order_relaxed);
      p.best_log_posterior = std::max(p.best_log_posterior, c.best.load(std::memory_order_relaxed));
    }
    p.current_log_posterior = monitor.chains[0].current.load(std::memory_order_relaxed);
    p.acceptance_rate = selected == 0 ? 0.0 : static_cast<double>(accepted) / static_cast<double>(selected);
    p.seconds = seconds_since(start);
    p.finished = finished;
    cfg.progress(p);
  };

  std::vector<std::thread> threads;
  threads.reserve(workers);
  for (unsigned w = 0; w < workers; ++w) threads.emplace_back(worker);
  std::exception_ptr progress_error;
  {
    const auto interval = std::chrono::duration<double>(std::max(cfg.progress_interval_s, 0.01));
    std::unique_lock<std::mutex> lock(monitor.mutex);
    while (monitor.finished < n) {
      monitor.cv.wait_for(lock, interval);
      if (monitor.finished < n && !progress_error) {
        lock.unlock();
        try {
          report(false);
        } catch (...) {
          progress_error = std::current_exception();  // stop the chains, rethrow after joining
          abort.store(true);
        }
        lock.lock();
      }
    }
  }
  for (auto& t : threads) t.join();
  if (progress_error) std::rethrow_exception(progress_error);

  for (unsigned c = 0; c < n; ++c) {
    if (!errors[c]) continue;
    try {
      std::rethrow_exception(errors[c]);
    } catch (const std::exception& e) {
      std::throw_with_nested(std::runtime_error(fmt::format("chain {}: {}", c, e.what())));  // keeps the cause's type
    }
  }

  RunResult out;
  out.kernels.resize(kernels_.size());
  for (std::size_t k = 0; k < kernels_.size(); ++k) out.kernels[k].name = kernels_[k]->name();
  for (unsigned c = 0; c < n; ++c) {
    const ChainResult& r = results[c];
    for (std::size_t k = 0; k < kernels_.size(); ++k) out.kernels[k] += r.kernels[k];
    out.iterations += r.iterations;
    out.cancelled = out.cancelled || r.cancelled;
    if (r.best_log_posterior > results[out.best_chain].best_log_posterior) out.best_chain = c;
  }
  out.chains = std::move(results);
  out.seconds = seconds_since(start);
  report(true);
  return out;
}

}  // namespace ksmc::runtime::mcmc
