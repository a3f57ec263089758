// (b) The reusable detailed-balance checker on the toy kernels, and on a broken kernel.
#include <catch2/catch.hpp>

#include <cstdio>

#include "tests/mcmc/detailed_balance.h"
#include "tests/mcmc/toy_model.h"

namespace rm = ksmc::runtime::mcmc;
using namespace ksmc::tests::mcmc;

namespace {

std::vector<rm::Snapshot> all_states(int n) {
  std::vector<rm::Snapshot> s;
  for (int x = 0; x < n; ++x) s.push_back(rm::Snapshot{{"x", x}});
  return s;
}

}  // namespace

TEST_CASE("UP/DOWN pair satisfies detailed balance on every state") {
  auto model = toy_factory()(0);
  const auto kernels = toy_kernels();
  rm::Rng rng(3);
  DetailedBalanceOptions opt;
  opt.draws = 6000;
  const auto report =
      check_kernel_pair(*model, *kernels[0], *kernels[1], all_states(20), 0.3, 0.5, rng, opt);
  std::printf("UP/DOWN: %s\n", report.summary().c_str());
  CHECK(report.transitions == 3 * 17 + 2 + 1);  // x <= 16: 3 moves, x = 17: 2, x = 18: 1
  CHECK(report.ok());
  // And the other direction of the pair.
  const auto back =
      check_kernel_pair(*model, *kernels[1], *kernels[0], all_states(20), 0.5, 0.3, rng, opt);
  CHECK(back.ok());
}

TEST_CASE("self-reverse RESAMPLE satisfies detailed balance") {
  auto model = toy_factory()(0);
  const auto kernels = toy_kernels();
  rm::Rng rng(4);
  DetailedBalanceOptions opt;
  opt.draws = 5000;
  const auto report =
      check_kernel_pair(*model, *kernels[2], *kernels[2], all_states(4), 0.2, 0.2, rng, opt);
  std::printf("RESAMPLE: %s\n", report.summary().c_str());
  CHECK(report.transitions == 4 * 20);
  CHECK(report.ok());
}

TEST_CASE("the checker catches a kernel whose reverse density disagrees") {
  auto model = toy_factory()(0);
  const auto bad = toy_kernels(0.3);  // UP reports log_q_bwd 0.3 too high
  rm::Rng rng(5);
  DetailedBalanceOptions opt;
  opt.draws = 2000;
  const auto report = check_kernel_pair(*model, *bad[0], *bad[1], all_states(5), 0.3, 0.5, rng, opt);
  CHECK_FALSE(report.ok());
  CHECK(report.max_log_q_mismatch == Approx(0.3));
  CHECK(report.max_balance_error > 1e-3);
}

namespace {

// Reports the right densities but does not restore on reject.
class LeakyModel : public ToyModel {
 public:
  using ToyModel::ToyModel;
  void reject() override {}
};

}  // namespace

TEST_CASE("the checker catches a model whose reject() does not restore") {
  LeakyModel model(std::make_shared<const std::vector<double>>(toy_log_target()), 0);
  const auto kernels = toy_kernels();
  rm::Rng rng(6);
  DetailedBalanceOptions opt;
  opt.draws = 200;
  const auto report = check_kernel_pair(model, *kernels[0], *kernels[1], all_states(3), 0.3, 0.5, rng, opt);
  CHECK_FALSE(report.ok());
  REQUIRE_FALSE(report.failures.empty());
  CHECK(report.failures.front().find("reject() did not restore") != std::string::npos);
}
