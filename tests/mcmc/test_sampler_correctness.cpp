// (a) The sampler reaches the right distribution on an enumerable toy posterior with
// asymmetric proposals and unequal kernel-selection probabilities.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

#include "runtime/mcmc/engine.h"
#include "tests/mcmc/toy_model.h"

namespace rm = ksmc::runtime::mcmc;
using namespace ksmc::tests::mcmc;

namespace {

// Runs one long chain and returns the total-variation distance between its empirical
// distribution (after burn-in) and the enumerated posterior.
double run_tv(const rm::KernelList& kernels, const rm::Schedule& schedule, std::uint64_t iterations,
              std::uint64_t seed) {
  const int n = 20;
  rm::Engine engine(toy_factory(0, n), kernels, schedule);
  std::vector<std::uint64_t> hist(n, 0);
  rm::EngineConfig cfg;
  cfg.iterations = iterations;
  cfg.seed = seed;
  cfg.burn_in = 1000;
  cfg.thin = 1;
  cfg.observer = [&hist](unsigned, std::uint64_t, const rm::Model& m) {
    ++hist[static_cast<std::size_t>(static_cast<const ToyModel&>(m).x())];
  };
  const rm::RunResult res = engine.run(cfg);
  REQUIRE(res.iterations == iterations);
  std::uint64_t total = 0;
  for (auto h : hist) total += h;
  REQUIRE(total == iterations - 1000);
  const std::vector<double> p = normalised(toy_log_target(n));
  double tv = 0.0;
  for (int x = 0; x < n; ++x) {
    tv += std::fabs(static_cast<double>(hist[static_cast<std::size_t>(x)]) / static_cast<double>(total) -
                    p[static_cast<std::size_t>(x)]);
  }
  return 0.5 * tv;
}

rm::Schedule toy_schedule(const rm::KernelList& kernels) {
  // Three rows, as in the dissertation's Table 3.2; every row leaves the target invariant.
  return rm::Schedule(rm::kernel_infos(kernels),
                      {{0, 1000, {{"RESAMPLE", 1.0}}},
                       {1000, 600000, {{"UP", 0.3}, {"DOWN", 0.5}, {"RESAMPLE", 0.2}}},
                       {600000, rm::kForever, {{"UP", 0.45}, {"DOWN", 0.55}}}});
}

}  // namespace

TEST_CASE("long chain matches the enumerated posterior (TV <= 0.02)") {
  const auto kernels = toy_kernels();
  const double tv = run_tv(kernels, toy_schedule(kernels), 2'000'000, 42);
  std::printf("toy posterior, 2e6 iterations, seed 42: total-variation distance = %.5f\n", tv);
  CHECK(tv <= 0.02);
}

TEST_CASE("a kernel reporting a wrong reverse density is detected (TV clearly > 0.02)") {
  // Negative control: UP claims log Q(M|M') 0.7 too high; the stationary law shifts.
  const auto kernels = toy_kernels(0.7);
  const double tv = run_tv(kernels, toy_schedule(kernels), 2'000'000, 42);
  std::printf("toy posterior with a dishonest UP kernel: total-variation distance = %.5f\n", tv);
  CHECK(tv > 0.05);
}

TEST_CASE("kernel-selection probabilities enter the acceptance ratio") {
  // Only UP/DOWN with very unequal selection: without the Phi(R)/Phi(K) term the chain
  // would drift towards x = 0.
  const auto all = toy_kernels();
  const rm::KernelList kernels = {all[0], all[1]};
  const rm::Schedule schedule = rm::Schedule::constant(rm::kernel_infos(kernels),
                                                       {{"UP", 0.2}, {"DOWN", 0.8}});
  const double tv = run_tv(kernels, schedule, 2'000'000, 7);
  std::printf("toy posterior, UP 0.2 / DOWN 0.8: total-variation distance = %.5f\n", tv);
  CHECK(tv <= 0.02);
}

namespace {

// Delayed acceptance around a toy kernel: a first stage on the likelihood alone with
// α1 = min(1, r1 e^margin), declined when it fails; a passing proposal reports
// log α1(x→y) - log α1(y→x) so that the engine's test is the second stage. `correct = false`
// reports nothing (a model that forgets the correction: the negative control).
class ScreenedKernel : public rm::Kernel {
 public:
  ScreenedKernel(std::shared_ptr<const rm::Kernel> inner, double margin, bool correct)
      : inner_(std::move(inner)), margin_(margin), correct_(correct) {}
  std::string_view name() const override { return inner_->name(); }
  std::string_view reverse_name() const override { return inner_->reverse_name(); }
  rm::Proposal propose(rm::Model& model, rm::Rng& rng) const override {
    const double before = model.log_likelihood();
    const rm::Proposal p = inner_->propose(model, rng);
    if (p.was_declined()) return p;
    const double r1 = model.log_likelihood() - before + p.log_q_bwd - p.log_q_fwd;
    const double fwd = std::min(0.0, r1 + margin_), bwd = std::min(0.0, margin_ - r1);
    if (fwd < 0.0 && !(std::log(rng.uniform_pos()) < fwd)) {
      model.reject();
      return rm::Proposal::declined();
    }
    return rm::Proposal::made(p.log_q_fwd, p.log_q_bwd, correct_ ? fwd - bwd : 0.0);
  }

 private:
  std::shared_ptr<const rm::Kernel> inner_;
  double margin_;
  bool correct_;
};

rm::KernelList screened(const rm::KernelList& kernels, double margin, bool correct) {
  rm::KernelList out;
  for (const auto& k : kernels) out.push_back(std::make_shared<ScreenedKernel>(k, margin, correct));
  return out;
}

}  // namespace

TEST_CASE("delayed acceptance (Proposal::log_screened) keeps the posterior") {
  // Margin 0.2 nats: most moves face the first stage. The likelihood is the cheap part, the
  // prior (-0.05 x) the part the engine's second stage tests.
  const auto kernels = screened(toy_kernels(), 0.2, true);
  const double tv = run_tv(kernels, toy_schedule(kernels), 2'000'000, 42);
  std::printf("toy posterior, delayed acceptance: total-variation distance = %.5f\n", tv);
  CHECK(tv <= 0.02);
  // Negative control: the same first stage without the engine-side correction is biased.
  const auto wrong = screened(toy_kernels(), 0.2, false);
  const double tv_wrong = run_tv(wrong, toy_schedule(wrong), 2'000'000, 42);
  std::printf("toy posterior, first stage not corrected: total-variation distance = %.5f\n", tv_wrong);
  CHECK(tv_wrong > 0.05);
}
