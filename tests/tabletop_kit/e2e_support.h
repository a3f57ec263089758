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
  Counts& operator+=(const Counts& o) {
    tp += o.tp;
    fp += o.fp;
    fn += o.fn;
    return *this;
  }
  std::string row(const std::string& name) const {
    return fmt::format("| {:<14} | {:>4} | {:>4} | {:>4} | {:>9.3f} | {:>6.3f} | {:>6.3f} |", name, tp, fp, fn,
                       precision(), recall(), f1());
  }
};

struct Score {
  Counts is_false, is_hidden, support, contact;
  long undecided = 0;           // false/hidden with probability in [0.4, 0.6]
  long objects = 0;
  long positives = 0;           // objects truly false or hidden
  long positive_undecided = 0;  // of those, undecided on the predicate that is true
  Score& operator+=(const Score& o) {
    is_false += o.is_false;
    is_hidden += o.is_hidden;
    support += o.support;
    contact += o.contact;
    undecided += o.undecided;
    objects += o.objects;
    positives += o.positives;
    positive_undecided += o.positive_undecided;
    return *this;
  }
};

// A truth id as the kit's scene stores it: numeric ids as their JSON text.
inline std::string truth_id(const nlohmann::json& id) { return id.is_string() ? id.get<std::string>() : id.dump(); }

// An unordered pair, smaller id first.
inline std::pair<std::string, std::string> unordered(std::string a, std::string b) {
  if (b < a) std::swap(a, b);
  return {a, b};
}

// Adds one scene: prediction = the kit's result, truth = generator's truth.json.
inline void score(const tt::TabletopResult& r, const nlohmann::json& truth, Score& s) {
  for (const auto& t : truth.at("objects")) {
    const int i = r.scene.find(truth_id(t.at("id")));
    if (i < 0) throw std::runtime_error("truth object missing from the scene");
    const auto& p = r.probabilities[static_cast<std::size_t>(i)];
    const auto f = tt::decide(p.false_prob), h = tt::decide(p.hidden_prob);
    const bool is_false = t.at("false").get<bool>(), is_hidden = t.at("hidden").get<bool>();
    if (!f || !h) ++s.undecided;
    ++s.objects;
    if (is_false || is_hidden) {
      ++s.positives;
      if ((is_false && !f) || (is_hidden && !h)) ++s.positive_undecided;
    }
    s.is_false.add(f.value_or(false), is_false);
    s.is_hidden.add(h.value_or(false), is_hidden);
  }
  auto add_edges = [](const std::set<std::pair<std::string, std::string>>& predicted,
                      const std::set<std::pair<std::string, std::string>>& truth_edges, Counts& c) {
    for (const auto& e : predicted) c.add(true, truth_edges.count(e) > 0);
    for (const auto& e : truth_edges)
      if (!predicted.count(e)) c.add(false, true);
  };
  std::set<std::pair<std::string, std::string>> predicted, truth_edges, predicted_contact, truth_contact;
  for (const auto& e : tt::support_edges(r)) predicted.insert(e);
  for (const auto& e : truth.at("support")) truth_edges.insert({truth_id(e.at(0)), truth_id(e.at(1))});
  add_edges(predicted, truth_edges, s.support);
  for (const auto& e : tt::unstable_contact_edges(r)) predicted_contact.insert(unordered(e.first, e.second));
  if (truth.contains("contact"))
    for (const auto& e : truth.at("contact")) truth_contact.insert(unordered(truth_id(e.at(0)), truth_id(e.at(1))));
  add_edges(predicted_contact, truth_contact, s.contact);
}

inline std::string table(const Score& s) {
  return "| relation       |   tp |   fp |   fn | precision | recall |     F1 |\n"
         "|----------------|-----:|-----:|-----:|----------:|-------:|-------:|\n" +
         s.is_false.row("false") + "\n" + s.is_hidden.row("hidden") + "\n" + s.support.row("support edges") + "\n" +
         fmt::format("undecided (0.4 <= p <= 0.6) object decisions: {}\n", s.undecided);
}

}  // namespace ksmc::tests::tabletop_kit
