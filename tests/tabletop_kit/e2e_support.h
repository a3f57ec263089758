// Shared pieces of the end-to-end tests and the benchmark: run the kit's sampler on a
// scene and score scene graphs against generator truth.
#pragma once

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/mcmc/engine.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "stdlib/tabletop/result.h"
#include "tests/tabletop_kit/binding_fixture.h"

namespace ksmc::tests::tabletop_kit {

namespace kit = ksmc::stdlib::tabletop::kit;
namespace tt = ksmc::stdlib::tabletop;

// Runs one chain and returns the result at the best state.
inline tt::TabletopResult run_kit(const blk::Binding& binding, std::shared_ptr<const tt::Scene> scene,
                                  std::uint64_t iterations, std::uint64_t seed, kit::KitOptions options = {}) {
  kit::KitSetup k = kit::make_setup(binding, scene, options);
  runtime::mcmc::Engine engine(k.setup.model_factory, k.setup.kernels, k.setup.schedule);
  runtime::mcmc::EngineConfig ec;
  ec.iterations = iterations;
  ec.seed = seed;
  const runtime::mcmc::RunResult r = engine.run(ec);
  auto best = k.setup.model_factory(0);
  best->restore(r.best().best_state);
  return kit::result_of(static_cast<const kit::TabletopModel&>(*best));
}

struct Counts {
  long tp = 0, fp = 0, fn = 0;
  void add(bool predicted, bool truth) {
    if (predicted && truth) ++tp;
    else if (predicted) ++fp;
    else if (truth) ++fn;
  }
  double precision() const { return tp + fp == 0 ? 1.0 : static_cast<double>(tp) / static_cast<double>(tp + fp); }
  double recall() const { return tp + fn == 0 ? 1.0 : static_cast<double>(tp) / static_cast<double>(tp + fn); }
  double f1() const {
    const double p = precision(), r = recall();
    return p + r == 0.0 ? 0.0 : 2.0 * p * r / (p + r);
  }
  std::string row(const std::string& name) const {
    return fmt::format("| {:<14} | {:>4} | {:>4} | {:>4} | {:>9.3f} | {:>6.3f} | {:>6.3f} |", name, tp, fp, fn,
                       precision(), recall(), f1());
  }
};

struct Score {
  Counts is_false, is_hidden, support;
  long undecided = 0;  // false/hidden with probability in [0.4, 0.6]
};

// Adds one scene: prediction = the kit's result, truth = generator's truth.json.
inline void score(const tt::TabletopResult& r, const nlohmann::json& truth, Score& s) {
  for (const auto& t : truth.at("objects")) {
    const int i = r.scene.find(t.at("id").get<std::string>());
    if (i < 0) throw std::runtime_error("truth object missing from the scene");
    const auto& p = r.probabilities[static_cast<std::size_t>(i)];
    const auto f = tt::decide(p.false_prob), h = tt::decide(p.hidden_prob);
    if (!f || !h) ++s.undecided;
    s.is_false.add(f.value_or(false), t.at("false").get<bool>());
    s.is_hidden.add(h.value_or(false), t.at("hidden").get<bool>());
  }
  std::set<std::pair<std::string, std::string>> predicted, truth_edges;
  for (const auto& e : tt::support_edges(r.evidence)) predicted.insert(e);
  for (const auto& e : truth.at("support")) truth_edges.insert({e.at(0).get<std::string>(), e.at(1).get<std::string>()});
  for (const auto& e : predicted) s.support.add(true, truth_edges.count(e) > 0);
  for (const auto& e : truth_edges)
    if (!predicted.count(e)) s.support.add(false, true);
}

inline std::string table(const Score& s) {
  return "| relation       |   tp |   fp |   fn | precision | recall |     F1 |\n"
         "|----------------|-----:|-----:|-----:|----------:|-------:|-------:|\n" +
         s.is_false.row("false") + "\n" + s.is_hidden.row("hidden") + "\n" + s.support.row("support edges") + "\n" +
         fmt::format("undecided (0.4 <= p <= 0.6) object decisions: {}\n", s.undecided);
}

}  // namespace ksmc::tests::tabletop_kit
