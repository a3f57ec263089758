// (c) reproducibility, (d) declined proposals, traces, samples, best state, cancellation,
// error propagation.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "runtime/mcmc/engine.h"
#include "tests/mcmc/toy_model.h"

namespace rm = ksmc::runtime::mcmc;
using namespace ksmc::tests::mcmc;

namespace {

rm::Engine toy_engine() {
  const auto kernels = toy_kernels();
  return rm::Engine(toy_factory(0), kernels,
                    rm::Schedule(rm::kernel_infos(kernels),
                                 {{0, 100, {{"UP", 1.0 / 3}, {"DOWN", 1.0 / 3}, {"RESAMPLE", 1.0 / 3}}},
                                  {100, rm::kForever, {{"UP", 0.4}, {"DOWN", 0.6}}}}));
}

rm::EngineConfig base_config(unsigned chains, unsigned threads) {
  rm::EngineConfig cfg;
  cfg.iterations = 20000;
  cfg.seed = 1234;
  cfg.chains = chains;
  cfg.threads = threads;
  cfg.trace_every = 500;
  cfg.burn_in = 10000;
  cfg.samples = 50;
  cfg.thin = 100;
  return cfg;
}

void require_same(const rm::RunResult& a, const rm::RunResult& b) {
  REQUIRE(a.chains.size() == b.chains.size());
  CHECK(a.best_chain == b.best_chain);
  CHECK(a.kernels == b.kernels);
  for (std::size_t c = 0; c < a.chains.size(); ++c) {
    const auto& x = a.chains[c];
    const auto& y = b.chains[c];
    CHECK(x.trace == y.trace);
    CHECK(x.kernels == y.kernels);
    CHECK(x.best_state == y.best_state);
    CHECK(x.best_iteration == y.best_iteration);
    CHECK(x.best_log_posterior == y.best_log_posterior);
    CHECK(x.final_log_posterior == y.final_log_posterior);
    REQUIRE(x.samples.size() == y.samples.size());
    for (std::size_t s = 0; s < x.samples.size(); ++s) {
      CHECK(x.samples[s].iteration == y.samples[s].iteration);
      CHECK(x.samples[s].state == y.samples[s].state);
    }
  }
}

}  // namespace

TEST_CASE("same seed gives the identical run with one chain") {
  const auto engine = toy_engine();
  const auto a = engine.run(base_config(1, 1));
  const auto b = engine.run(base_config(1, 1));
  require_same(a, b);
  CHECK(a.chains[0].trace.size() == 40);
  CHECK(a.chains[0].samples.size() == 50);
  CHECK(a.chains[0].samples.front().iteration == 10100);
  CHECK(a.chains[0].samples.back().iteration == 15000);

  auto other = base_config(1, 1);
  other.seed = 1235;
  const auto c = engine.run(other);
  CHECK_FALSE(c.chains[0].trace == a.chains[0].trace);
}

TEST_CASE("same seed gives the identical merged run with 4 chains, whatever the threads") {
  const auto engine = toy_engine();
  const auto a = engine.run(base_config(4, 4));
  const auto b = engine.run(base_config(4, 4));
  const auto serial = engine.run(base_config(4, 1));
  require_same(a, b);
  require_same(a, serial);
  // Chains are distinct streams; chain 0 equals the single-chain run.
  CHECK_FALSE(a.chains[0].trace == a.chains[1].trace);
  require_same(engine.run(base_config(1, 1)), [&] {
    rm::RunResult only0;
    only0.chains = {a.chains[0]};
    only0.kernels = a.chains[0].kernels;
    return only0;
  }());
  // Merged counts and the best chain.
  std::uint64_t selected = 0;
  for (const auto& k : a.kernels) selected += k.selected;
  CHECK(selected == 4 * 20000);
  CHECK(a.iterations == 4 * 20000);
  for (const auto& c : a.chains) CHECK(c.best_log_posterior <= a.best().best_log_posterior);
}

TEST_CASE("best state is the highest posterior visited and restores to it") {
  const auto engine = toy_engine();
  auto cfg = base_config(2, 2);
  const auto res = engine.run(cfg);
  const auto& best = res.best();
  auto model = toy_factory()(0);
  model->restore(best.best_state);
  CHECK(model->log_posterior() == Approx(best.best_log_posterior));
  // The toy target's mode is x = 4.
  CHECK(best.best_state.at("x").get<int>() == 4);
  for (const auto& t : best.trace) CHECK(t.log_posterior <= best.best_log_posterior);
}

TEST_CASE("declined proposals are counted as rejections") {
  const auto all = toy_kernels();
  const rm::KernelList kernels = {all[0], all[1], std::make_shared<DeclineKernel>()};
  rm::Engine engine(toy_factory(0), kernels,
                    rm::Schedule::constant(rm::kernel_infos(kernels),
                                           {{"UP", 0.25}, {"DOWN", 0.25}, {"NOPE", 0.5}}));
  rm::EngineConfig cfg;
  cfg.iterations = 10000;
  cfg.trace_every = 1000;
  const auto res = engine.run(cfg);
  REQUIRE(res.chains[0].trace.size() == 10);
  for (const auto& t : res.chains[0].trace) {
    REQUIRE(t.kernel_acceptance_window.size() == 3);
    CHECK(t.kernel_acceptance_window[2] == 0.0);  // NOPE never accepted
    CHECK(t.kernel_acceptance_window[0] >= 0.0);
    CHECK(t.kernel_acceptance_window[0] <= 1.0);
  }
  const auto& up = res.kernels[0];
  const auto& down = res.kernels[1];
  const auto& nope = res.kernels[2];
  CHECK(nope.name == "NOPE");
  CHECK(nope.selected > 4000);
  CHECK(nope.declined == nope.selected);
  CHECK(nope.accepted == 0);
  CHECK(nope.rejected() == nope.selected);
  CHECK(nope.acceptance_rate() == 0.0);
  // DOWN from x = 0 declines; starting at 0, some DOWN proposals must have been declined.
  CHECK(down.declined > 0);
  CHECK(up.selected + down.selected + nope.selected == 10000);
  CHECK(res.acceptance_rate() < 0.5);
}

TEST_CASE("cancellation stops at the next iteration and keeps results") {
  const auto engine = toy_engine();
  std::atomic<bool> cancel{false};
  auto cfg = base_config(2, 2);
  cfg.iterations = 100'000'000;
  cfg.cancel = &cancel;
  cfg.observer = [&cancel](unsigned, std::uint64_t it, const rm::Model&) {
    if (it >= 12345) cancel.store(true);
  };
  const auto res = engine.run(cfg);
  CHECK(res.cancelled);
  for (const auto& c : res.chains) {
    CHECK(c.cancelled);
    CHECK(c.iterations < 100'000'000);
    CHECK_FALSE(c.best_state.is_null());
    REQUIRE_FALSE(c.trace.empty());
    CHECK(c.trace.back().iteration == c.iterations);  // final trace row written
  }
}

TEST_CASE("progress is reported with sane numbers and a final call") {
  const auto engine = toy_engine();
  auto cfg = base_config(2, 2);
  cfg.iterations = 200000;
  int calls = 0;
  rm::Progress last;
  cfg.progress = [&](const rm::Progress& p) {
    ++calls;
    CHECK(p.iterations_done <= p.iterations_total);
    last = p;
  };
  engine.run(cfg);
  CHECK(calls >= 1);
  CHECK(last.finished);
  CHECK(last.iterations_done == 400000);
  CHECK(last.acceptance_rate > 0.0);
}

TEST_CASE("per-kernel trace acceptance is NaN for kernels not selected in the window") {
  const auto engine = toy_engine();  // row [0, 100) has RESAMPLE, row [100, inf) does not
  rm::EngineConfig cfg;
  cfg.iterations = 1000;
  cfg.trace_every = 100;
  const auto res = engine.run(cfg);
  const auto& trace = res.chains[0].trace;
  REQUIRE(trace.size() == 10);
  CHECK_FALSE(std::isnan(trace[0].kernel_acceptance_window[2]));
  for (std::size_t i = 1; i < trace.size(); ++i) CHECK(std::isnan(trace[i].kernel_acceptance_window[2]));
}

TEST_CASE("an exception from the progress callback stops the run cleanly") {
  const auto engine = toy_engine();
  rm::EngineConfig cfg;
  cfg.iterations = 1'000'000'000;
  cfg.chains = 2;
  cfg.progress_interval_s = 0.01;
  cfg.progress = [](const rm::Progress&) { throw std::runtime_error("display broke"); };
  CHECK_THROWS_WITH(engine.run(cfg), "display broke");
}

namespace {

class ThrowingKernel : public rm::NamedKernel<ToyModel> {
 public:
  ThrowingKernel() : NamedKernel("BOOM", "BOOM") {}

 protected:
  rm::Proposal propose_typed(ToyModel& m, rm::Rng&) const override {
    if (m.proposals() > 50) throw std::runtime_error("kernel failed");
    m.move_to(m.x());
    return rm::Proposal::made(0.0, 0.0);
  }
};

}  // namespace

TEST_CASE("a kernel exception stops the run and names the chain") {
  const rm::KernelList kernels = {std::make_shared<ThrowingKernel>()};
  rm::Engine engine(toy_factory(0), kernels,
                    rm::Schedule::constant(rm::kernel_infos(kernels), {{"BOOM", 1.0}}));
  rm::EngineConfig cfg;
  cfg.chains = 3;
  // Every chain fails; which one fails first depends on timing, the message names it.
  CHECK_THROWS_WITH(engine.run(cfg), Catch::Matches("chain [0-2]: kernel failed"));
}

TEST_CASE("engine rejects a kernel table that does not match the schedule") {
  const auto kernels = toy_kernels();
  const auto schedule = rm::Schedule::constant(rm::kernel_infos(kernels), {{"RESAMPLE", 1.0}});
  const rm::KernelList swapped = {kernels[1], kernels[0], kernels[2]};
  CHECK_THROWS_AS(rm::Engine(toy_factory(), swapped, schedule), std::invalid_argument);
  CHECK_THROWS_AS(rm::Engine(toy_factory(), {}, rm::Schedule()), std::invalid_argument);
}

TEST_CASE("stop_at_plateau: each chain stops once its best stops gaining, whatever the threads") {
  const auto engine = toy_engine();
  auto cfg = base_config(4, 1);
  cfg.iterations = 1000000;
  cfg.burn_in = 0;
  cfg.samples = 5;
  cfg.thin = 10;
  cfg.keep_last_samples = true;
  cfg.stop_at_plateau = rm::PlateauCriterion{1000, 0.0};
  const auto a = engine.run(cfg);
  REQUIRE(a.chains.size() == 4);
  for (const auto& c : a.chains) {
    REQUIRE(c.plateau.has_value());
    CHECK_FALSE(c.cancelled);
    CHECK(c.iterations < cfg.iterations);
    CHECK(c.iterations % cfg.plateau_every == 0);
    CHECK(c.iterations == c.plateau->iteration + 1000);  // judged every 100, window a multiple of it
    CHECK(c.best_iteration <= c.plateau->iteration);
    CHECK(c.plateau->best == c.best_log_posterior);
    REQUIRE(c.samples.size() == 5);  // the last five, oldest first
    for (std::size_t s = 0; s < 5; ++s) CHECK(c.samples[s].iteration == c.iterations - 10 * (4 - s));
  }
  cfg.threads = 4;
  const auto b = engine.run(cfg);
  require_same(a, b);
  for (std::size_t c = 0; c < 4; ++c) CHECK(a.chains[c].iterations == b.chains[c].iterations);
}

TEST_CASE("stop_at_plateau: no plateau within the iterations, and bad criteria") {
  const auto engine = toy_engine();
  auto cfg = base_config(1, 1);
  cfg.iterations = 3000;
  cfg.stop_at_plateau = rm::PlateauCriterion{5000, 0.0};
  const auto r = engine.run(cfg);
  CHECK_FALSE(r.chains[0].plateau.has_value());
  CHECK(r.chains[0].iterations == 3000);
  cfg.stop_at_plateau = rm::PlateauCriterion{0, 0.0};
  CHECK_THROWS_AS(engine.run(cfg), std::invalid_argument);
  cfg.stop_at_plateau = rm::PlateauCriterion{100, -1.0};
  CHECK_THROWS_AS(engine.run(cfg), std::invalid_argument);
}

