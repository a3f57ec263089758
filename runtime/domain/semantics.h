// The evidence-keyed Markov logic evaluator every kit shares (the semantic half of a
// KSMCMC model): evaluates the generated extractors of a SemanticBinding over the scene's
// constants, closes the world (evidence atoms not true are false), and runs or recalls
// Markov logic inference for exactly that evidence (an LRU cache keyed by the evidence bits;
// fixed seeds, so an outcome is a pure function of the bits). Names of predicates, types and
// kernels never appear here: everything comes from the binding and the generated program.
//
// Typical kit use:
//   Semantics<Scene> sem(binding, {.log_map = true});
//   auto out = sem.evaluate(scene, n);               // all atoms
//   auto out = sem.update(scene, n, changed);        // only atoms touching changed constants
//   double p = sem.value(*out, pred, {i, j});        // marginal (query) or 0/1 (evidence)
//   double lp = sem.conditional_priors(scene, *out); // Σ terms of `prior for ... where ...`
//   json q = sem.queries_json(*out, names);          // {"Room": {"u3": 0.91}, "SaLe": {"u3,u7": 0.8}}
//   std::string db = sem.evidence_db(*out, names);   // Alchemy .db of the evidence atoms
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/domain/binding.h"

namespace ksmc::runtime::domain {

struct SemanticOptions {
  std::size_t cache_capacity = 256;
  std::uint64_t seed = 1;          // MC-SAT / MaxWalkSAT seeds for components too large to enumerate
  bool log_z = false;              // compute Outcome::log_z
  bool log_map = false;            // compute Outcome::log_map
  std::uint64_t mcsat_samples = 500;
  std::uint64_t mcsat_burn_in = 50;
};

struct Outcome {
  std::size_t constants = 0;  // run-time constants of the binding's constant type
  // Per predicate of the program (program order), flat over the argument constants (mixed
  // radix, first argument most significant, as mln::Evidence): evidence atoms 0 / 1, query
  // atoms their marginal probability.
  std::vector<std::vector<double>> values;
  double log_z = 0.0;    // with SemanticOptions::log_z; -inf when a hard rule is violated
  double log_map = 0.0;  // with SemanticOptions::log_map: Σ w n of the most probable world
  bool exact = true;     // every component was enumerated / eliminated exactly
  std::string method;    // of the inference run
};

struct SemanticStats {
  std::uint64_t evaluations = 0, cache_hits = 0, inferences = 0, extractor_calls = 0;
  double inference_seconds = 0.0;
};

// Type-erased core (semantics.cpp); Semantics<Scene> below adds the scene.
class SemanticsCore {
 public:
  SemanticsCore(const MlnBinding& mln, std::int32_t constant_type, std::vector<std::int32_t> extracted,
                SemanticOptions options);

  const mln::Program& program() const { return *program_; }
  std::int32_t constant_type() const { return constant_type_; }
  // Predicates an extractor computes (program ids, binding order).
  const std::vector<std::int32_t>& extracted() const { return extracted_; }

  // Evidence bits for n constants: `truth(k, args)` evaluates extractor k on an atom.
  // `changed` empty with full = true: every atom; otherwise only atoms with an argument in
  // `changed` are re-evaluated, the rest are taken from the previous call with the same n.
  template <class F>
  std::shared_ptr<const Outcome> run(std::size_t n, bool full, std::span<const std::int32_t> changed, F&& truth);

  double value(const Outcome& o, std::int32_t predicate, std::span<const std::int32_t> args) const;
  bool holds(const Outcome& o, const Condition& c, std::span<const std::int32_t> binding) const;
  nlohmann::json queries_json(const Outcome& o, const std::vector<std::string>& names) const;
  std::string evidence_db(const Outcome& o, const std::vector<std::string>& names) const;
  const SemanticStats& stats() const { return stats_; }
  // Number of constants of `type` for n run-time constants (enumerated ones included).
  std::size_t constants_of(std::int32_t type, std::size_t n) const;

 private:
  std::shared_ptr<const Outcome> infer_bits(std::size_t n);

  MlnBinding mln_;
  const mln::Program* program_ = nullptr;
  std::int32_t constant_type_ = -1;
  std::vector<std::int32_t> extracted_;
  SemanticOptions options_;
  SemanticStats stats_;
  std::size_t bits_n_ = 0;
  std::vector<std::vector<std::uint8_t>> bits_;  // per extracted predicate, flat
  struct Cache;
  std::shared_ptr<Cache> cache_;
};

template <class Scene>
class Semantics {
 public:
  Semantics(const SemanticBinding<Scene>& binding, SemanticOptions options = {})
      : binding_(binding), core_(binding.mln, binding.constant_type, predicates_of(binding), options) {}

  std::shared_ptr<const Outcome> evaluate(const Scene& scene, std::size_t n) {
    return core_.run(n, true, {}, truth(scene));
  }
  std::shared_ptr<const Outcome> update(const Scene& scene, std::size_t n, std::span<const std::int32_t> changed) {
    return core_.run(n, false, changed, truth(scene));
  }
  double value(const Outcome& o, std::int32_t predicate, std::span<const std::int32_t> args) const {
    return core_.value(o, predicate, args);
  }
  // Σ over the conditional priors and their bindings whose conditions hold of the term.
  double conditional_priors(const Scene& scene, const Outcome& o) const;
  nlohmann::json queries_json(const Outcome& o, const std::vector<std::string>& names) const {
    return core_.queries_json(o, names);
  }
  std::string evidence_db(const Outcome& o, const std::vector<std::string>& names) const {
    return core_.evidence_db(o, names);
  }
  const SemanticsCore& core() const { return core_; }
  const SemanticBinding<Scene>& binding() const { return binding_; }

 private:
  static std::vector<std::int32_t> predicates_of(const SemanticBinding<Scene>& b) {
    std::vector<std::int32_t> p;
    for (const auto& e : b.extractors) p.push_back(e.predicate);
    return p;
  }
  auto truth(const Scene& scene) {
    return [this, &scene](std::size_t k, const std::int32_t* args) { return binding_.extractors[k].eval(scene, args); };
  }

  const SemanticBinding<Scene>& binding_;
  SemanticsCore core_;
};

}  // namespace ksmc::runtime::domain
