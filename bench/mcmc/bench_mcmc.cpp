// Sampler overhead per iteration with no-op kernels (the engine's own cost: kernel pick,
// virtual calls, acceptance test, counters, cancellation poll). Median of several runs.
//
//   bench_mcmc [--iterations N] [--runs R]
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "runtime/mcmc/engine.h"

namespace rm = ksmc::runtime::mcmc;

namespace {

// Constant posterior: the cheapest possible model.
class NoopModel : public rm::Model {
 public:
  double log_likelihood() const override { return ll_; }
  double log_prior() const override { return 0.0; }
  void accept() override {}
  void reject() override {}
  rm::Snapshot snapshot() const override { return rm::Snapshot{{"noop", true}}; }
  void restore(const rm::Snapshot&) override {}

 private:
  double ll_ = -1.0;
};

// mode 0: Q ratio 1 (only the schedule's selection ratio Phi(R)/Phi(K) is left)
// mode 1: Q ratio exp(-0.5) on top: a uniform and a log on most iterations
// mode 2: always declines
class NoopKernel : public rm::Kernel {
 public:
  NoopKernel(std::string name, std::string reverse, int mode)
      : name_(std::move(name)), reverse_(std::move(reverse)), mode_(mode) {}
  std::string_view name() const override { return name_; }
  std::string_view reverse_name() const override { return reverse_; }
  rm::Proposal propose(rm::Model&, rm::Rng&) const override {
    if (mode_ == 2) return rm::Proposal::declined();
    return rm::Proposal::made(mode_ == 1 ? 0.5 : 0.0, 0.0);
  }

 private:
  std::string name_;
  std::string reverse_;
  int mode_;
};

struct Case {
  const char* label;
  int mode;
  unsigned chains;
  std::uint64_t trace_every;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t iterations = 5'000'000;
  int runs = 7;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--iterations") == 0) iterations = std::strtoull(argv[i + 1], nullptr, 10);
    else if (std::strcmp(argv[i], "--runs") == 0) runs = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: bench_mcmc [--iterations N] [--runs R]\n");
      return 2;
    }
  }
  if (iterations == 0 || runs < 1) {
    std::fprintf(stderr, "bench_mcmc: --iterations and --runs must be positive\n");
    return 2;
  }

  const std::vector<Case> cases = {
      {"neutral move, 1 chain", 0, 1, 0},
      {"MH test, 1 chain", 1, 1, 0},
      {"declined, 1 chain", 2, 1, 0},
      {"MH test + trace/100, 1 chain", 1, 1, 100},
      {"MH test, 2 chains (2 threads)", 1, 2, 0},
  };

  std::printf("bench_mcmc: %llu iterations per chain, median of %d runs, 4 kernels (2 pairs), schedule of 2 rows\n\n",
              static_cast<unsigned long long>(iterations), runs);
  // Wall time per chain-iteration (chains run concurrently), and process CPU time per
  // chain-iteration: on a loaded shared machine the CPU column is the engine's real cost.
  std::printf("%-32s %14s %10s %10s %14s %12s\n", "case", "wall ns/iter", "min", "max", "cpu ns/iter",
              "Mit/s total");
  for (const Case& c : cases) {
    const rm::KernelList kernels = {std::make_shared<NoopKernel>("A", "B", c.mode),
                                    std::make_shared<NoopKernel>("B", "A", c.mode),
                                    std::make_shared<NoopKernel>("C", "D", c.mode),
                                    std::make_shared<NoopKernel>("D", "C", c.mode)};
    rm::Schedule schedule(rm::kernel_infos(kernels),
                          {{0, 1000, {{"A", 0.5}, {"B", 0.5}}},
                           {1000, rm::kForever, {{"A", 0.2}, {"B", 0.3}, {"C", 0.25}, {"D", 0.25}}}});
    rm::Engine engine([](unsigned) { return std::make_unique<NoopModel>(); }, kernels, schedule);
    rm::EngineConfig cfg;
    cfg.iterations = iterations;
    cfg.chains = c.chains;
    cfg.threads = c.chains;
    cfg.trace_every = c.trace_every;
    std::vector<double> ns;
    std::vector<double> cpu_ns;
    for (int r = 0; r < runs; ++r) {
      cfg.seed = static_cast<std::uint64_t>(r + 1);
      const std::clock_t c0 = std::clock();
      const auto t0 = std::chrono::steady_clock::now();
      const rm::RunResult res = engine.run(cfg);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double cpu_s = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      cpu_ns.push_back(cpu_s * 1e9 / static_cast<double>(iterations * c.chains));
      if (res.iterations != iterations * c.chains) {
        std::fprintf(stderr, "bench_mcmc: run stopped early\n");
        return 1;
      }
      // Wall time per iteration of one chain (chains run concurrently).
      ns.push_back(s * 1e9 / static_cast<double>(iterations));
    }
    const double med = median(ns);
    std::printf("%-32s %14.1f %10.1f %10.1f %14.1f %12.1f\n", c.label, med, *std::min_element(ns.begin(), ns.end()),
                *std::max_element(ns.begin(), ns.end()), median(cpu_ns), 1e3 * c.chains / med);
  }
  std::printf("\ntarget: <= 1000 ns per iteration\n");
  return 0;
}
