// A toy domain for CLI tests: input is a JSON file {"n": 20, "start": 3}; flags
// --start-override INT, --interrupt-at INT (raises SIGINT after that many proposals, to
// test Ctrl-C handling) and --ready-file PATH (created at the first proposal, so a test
// driving the binary knows the run, and its Ctrl-C handler, has started).
#pragma once

#include <atomic>
#include <csignal>
#include <fstream>
#include <sstream>

#include "runtime/cli/domain_spec.h"
#include "tests/mcmc/toy_model.h"

namespace ksmc::tests::mcmc {

namespace cli = ksmc::runtime::cli;

class InterruptingKernel : public rm::NamedKernel<ToyModel> {
 public:
  explicit InterruptingKernel(long at) : NamedKernel("RESAMPLE", "RESAMPLE"), at_(at) {}

 protected:
  rm::Proposal propose_typed(ToyModel& m, rm::Rng& rng) const override {
    // Once only: the CLI's handler resets itself, a second SIGINT would end the test.
    if (m.proposals() >= at_ && !fired_.exchange(true)) std::raise(SIGINT);
    return inner_.propose(m, rng);
  }

 private:
  long at_;
  mutable std::atomic<bool> fired_{false};
  ResampleKernel inner_;
};

// Creates a file at its first proposal, then behaves like RESAMPLE.
class ReadyKernel : public rm::NamedKernel<ToyModel> {
 public:
  explicit ReadyKernel(std::string path) : NamedKernel("RESAMPLE", "RESAMPLE"), path_(std::move(path)) {}

 protected:
  rm::Proposal propose_typed(ToyModel& m, rm::Rng& rng) const override {
    if (!fired_.exchange(true)) std::ofstream(path_) << "running\n";
    return inner_.propose(m, rng);
  }

 private:
  std::string path_;
  mutable std::atomic<bool> fired_{false};
  ResampleKernel inner_;
};

inline cli::DomainSpec toy_domain_spec() {
  cli::DomainSpec spec;
  spec.name = "toy";
  spec.version = "1.2.3";
  spec.description = "toy domain: an integer on [0, n) with a two-bump posterior";
  spec.inputs_help = "toy.json";
  spec.default_iterations = 5000;
  spec.flags = {{"start-override", "initial x (overrides the input)", "", cli::DomainFlag::Kind::integer},
                {"interrupt-at", "raise SIGINT after this many proposals (tests)", "-1",
                 cli::DomainFlag::Kind::integer},
                {"ready-file", "file created when sampling starts (tests)", "", cli::DomainFlag::Kind::path}};
  spec.load = [](const cli::DomainInput& in) {
    const auto& path = in.inputs.at(0);
    std::ifstream f(path);
    if (!f) throw std::runtime_error(path.string() + ": cannot open");
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(f);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::runtime_error(path.string() + ": invalid JSON: " + e.what());
    }
    const int n = j.value("n", 0);
    if (n < 2) throw std::runtime_error(path.string() + ": \"n\" must be at least 2");
    int start = in.flags.has("start-override") ? static_cast<int>(in.flags.integer("start-override"))
                                               : j.value("start", 0);
    if (start < 0 || start >= n) throw cli::UsageError("start must be in [0, n)");
    const long interrupt_at = static_cast<long>(in.flags.integer("interrupt-at"));
    cli::DomainSetup s;
    s.model_factory = toy_factory(start, n);
    auto all = toy_kernels();
    if (interrupt_at >= 0) all[2] = std::make_shared<InterruptingKernel>(interrupt_at);
    if (in.flags.has("ready-file")) all[2] = std::make_shared<ReadyKernel>(in.flags.text("ready-file"));
    s.kernels = all;
    s.schedule = rm::Schedule(rm::kernel_infos(all),
                              {{0, 500, {{"RESAMPLE", 1.0}}},
                               {500, rm::kForever, {{"UP", 0.3}, {"DOWN", 0.4}, {"RESAMPLE", 0.3}}}});
    s.write_results = [](const rm::RunResult&, rm::Model& best, cli::OutputDir& out) {
      const auto& m = static_cast<const ToyModel&>(best);
      out.write("toy_result.json", nlohmann::json{{"x", m.x()}, {"log_posterior", m.log_posterior()}}.dump() + "\n");
    };
    s.summary_extra = {{"n", n}};
    return s;
  };
  return spec;
}

}  // namespace ksmc::tests::mcmc
