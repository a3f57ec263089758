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
//   auto out = sem.update(scene, n, changed, *base); // only atoms touching changed constants
//   double p = sem.value(*out, pred, {i, j});        // marginal (query) or 0/1 (evidence)
//   double lp = sem.conditional_priors(scene, *out); // Σ terms of `prior for ... where ...`
//   auto q = sem.queries_json(*out, names);          // {"Room": {"u3": 0.91}, "SaLe": {"u3,u7": 0.8}}
//   std::string db = sem.evidence_db(*out, names);   // Alchemy .db of the evidence atoms
//
// Constants. The constants of the binding's constant type are its enumerated constants (from
// the generated make_domain(), usually none) followed by the n run-time constants (the
// scene's elements in scene order). A constant index is that position; it is what extractors,
// terms, `value` and `changed` take. Other types have only their enumerated constants.
// `names` (queries_json, evidence_db) name the n run-time constants; internally they are
// anonymous.
//
// Evidence. Extractor k gives the truth of every ground atom of its predicate, except that
// an atom whose arguments repeat one constant of the constant type (`touching(a, a)`) is
// false without a call: relations hold between distinct scene elements. Evidence predicates
// without an extractor are false everywhere (closed world, as in a `.db` file).
//
// Outcomes. A hard rule violated by the evidence makes the outcome impossible: possible =
// false, log_z = log_map = -inf, query values 0. Inference is mln::infer with Method::Auto
// (exact per component when small enough, MC-SAT otherwise) and, with log_map, exact_map
// (MaxWalkSAT for a component too large to enumerate).
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/domain/binding.h"
#include "runtime/io/cancel.h"
#include "runtime/mln/evidence_cache.h"

namespace ksmc::runtime::domain {

struct SemanticOptions {
  std::size_t cache_capacity = 256;
  std::uint64_t seed = 1;          // MC-SAT / AIS / MaxWalkSAT seeds for components too large to enumerate
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
  bool possible = true;  // false: the evidence violates a hard rule
  bool exact = true;     // marginals, log Z and log MAP (those computed) are exact, not sampled
  std::string method;    // of the inference run ("none" when there is no atom)
};

struct SemanticStats {
  std::uint64_t evaluations = 0, cache_hits = 0, inferences = 0, extractor_calls = 0;
  double inference_seconds = 0.0;
};

// Type-erased core (semantics.cpp); Semantics<Scene> below adds the scene.
class SemanticsCore {
 public:
  // Throws ConfigError when the binding does not fit the program (incomplete Markov logic
  // binding, an extractor for a query predicate or an unknown one, two for one predicate,
  // an unknown constant type).
  SemanticsCore(const MlnBinding& mln, std::int32_t constant_type, std::vector<std::int32_t> extracted,
                SemanticOptions options);

  const mln::Program& program() const { return *program_; }
  std::int32_t constant_type() const { return constant_type_; }
  // Predicates an extractor computes (program ids, binding order).
  const std::vector<std::int32_t>& extracted() const { return extracted_; }
  // Query predicates (program ids, program order).
  const std::vector<std::int32_t>& queries() const { return queries_; }
  const SemanticOptions& options() const { return options_; }

  // Evidence bits for n run-time constants: `truth(k, args)` evaluates extractor k on an atom.
  // `full`: every atom. Otherwise only atoms with an argument in `changed` (constant indices)
  // are evaluated; the others are taken from `base` (an outcome for n constants) or, without
  // one, from the previous call (when it had the same n; else every atom is evaluated).
  template <class F>
  std::shared_ptr<const Outcome> run(std::size_t n, bool full, std::span<const std::int32_t> changed,
                                     const Outcome* base, F&& truth);
  // The outcome when no evidence atom holds, for n run-time constants (cached per n).
  std::shared_ptr<const Outcome> empty_evidence(std::size_t n);

  double value(const Outcome& o, std::int32_t predicate, std::span<const std::int32_t> args) const;
  bool holds(const Outcome& o, const Condition& c, std::span<const std::int32_t> binding) const;
  // {"Pred": {"c1,c2": p, ...}, ...}: every query predicate (program order), every ground
  // atom (constant order), marginals rounded to 1e-6. Ordered JSON: keys stay in that order.
  nlohmann::ordered_json queries_json(const Outcome& o, const std::vector<std::string>& names) const;
  // Alchemy `.db` text of every evidence atom: `P(a,b)` when true, `!P(a,b)` when false.
  std::string evidence_db(const Outcome& o, const std::vector<std::string>& names) const;
  const SemanticStats& stats() const { return stats_; }
  // Number of constants of `type` for n run-time constants (enumerated ones included).
  std::size_t constants_of(std::int32_t type, std::size_t n) const;
  // Enumerated constants of the constant type (they come before the run-time ones).
  std::size_t enumerated() const { return constants_of(constant_type_, 0); }
  // Name of constant `index` of `type`; run-time constants take theirs from `names`.
  const std::string& constant_name(std::int32_t type, std::int32_t index, const std::vector<std::string>& names) const;

 private:
  // One extracted predicate's shape for the current n.
  struct Shape {
    std::vector<std::int32_t> radix;
    std::vector<bool> of_constant_type;  // per argument
  };
  // Sizes bits_ for n and fills them from `base` / the previous call; true when every atom
  // must be evaluated. Marks `changed` in changed_.
  bool prepare(std::size_t n, bool full, std::span<const std::int32_t> changed, const Outcome* base);
  std::shared_ptr<const Outcome> finish(std::size_t n);
  std::shared_ptr<const Outcome> infer_bits(std::size_t n);
  std::size_t atoms_of(std::int32_t predicate, std::size_t n) const;
  void check_names(const Outcome& o, const std::vector<std::string>& names) const;

  MlnBinding mln_;
  const mln::Program* program_ = nullptr;
  mln::Domain base_domain_;  // the enumerated constants
  std::int32_t constant_type_ = -1;
  std::vector<std::int32_t> extracted_;
  std::vector<std::int32_t> queries_;
  SemanticOptions options_;
  SemanticStats stats_;
  bool have_bits_ = false;
  std::size_t bits_n_ = 0;
  std::vector<Shape> shapes_;                    // per extracted predicate
  std::vector<std::vector<std::uint8_t>> bits_;  // per extracted predicate, flat
  std::vector<std::uint8_t> changed_;            // per constant of the constant type
  mln::EvidenceCache<Outcome> cache_;
  std::map<std::size_t, std::shared_ptr<const Outcome>> empty_;
};

template <class F>
std::shared_ptr<const Outcome> SemanticsCore::run(std::size_t n, bool full, std::span<const std::int32_t> changed,
                                                  const Outcome* base, F&& truth) {
  const bool all = prepare(n, full, changed, base);
  std::vector<std::int32_t> args;
  // Evaluates one atom: false when two constant-type arguments repeat a constant.
  const auto visit = [&](std::size_t k, const Shape& shape, std::size_t flat) {
    bool repeated = false;
    for (std::size_t i = 0; i < args.size() && !repeated; ++i) {
      if (!shape.of_constant_type[i]) continue;
      for (std::size_t j = 0; j < i; ++j) repeated = repeated || (shape.of_constant_type[j] && args[j] == args[i]);
    }
    if (repeated) {
      bits_[k][flat] = 0;
      return;
    }
    if ((++stats_.extractor_calls & 0xFFF) == 0) io::throw_if_cancelled("evaluating the evidence");
    bits_[k][flat] = truth(k, args.data()) ? 1 : 0;
  };
  // The changed constants, ascending; the atoms they touch are enumerated directly, so a
  // proposal costs O(changed x n^(arity-1)) per predicate, not O(n^arity).
  std::vector<std::int32_t> moved;
  std::vector<std::size_t> stride;
  if (!all)
    for (std::size_t c = 0; c < changed_.size(); ++c)
      if (changed_[c] != 0) moved.push_back(static_cast<std::int32_t>(c));
  for (std::size_t k = 0; k < extracted_.size(); ++k) {
    const Shape& shape = shapes_[k];
    const std::size_t m = shape.radix.size();
    args.assign(m, 0);
    if (all) {
      for (std::size_t flat = 0; flat < bits_[k].size(); ++flat) {
        if (flat != 0)  // odometer: the last argument runs fastest
          for (std::size_t i = m; i-- > 0;) {
            if (++args[i] < shape.radix[i]) break;
            args[i] = 0;
          }
        visit(k, shape, flat);
      }
      continue;
    }
    if (bits_[k].empty()) continue;
    stride.assign(m, 1);
    for (std::size_t i = m; i-- > 1;) stride[i - 1] = stride[i] * static_cast<std::size_t>(shape.radix[i]);
    // An atom is visited once: in the pass of its first constant-type argument that changed.
    for (std::size_t at = 0; at < m; ++at) {
      if (!shape.of_constant_type[at]) continue;
      for (const std::int32_t c : moved) {
        if (c >= shape.radix[at]) break;
        std::fill(args.begin(), args.end(), 0);
        args[at] = c;
        for (;;) {
          bool earlier = false;
          for (std::size_t j = 0; j < at && !earlier; ++j)
            earlier = shape.of_constant_type[j] && changed_[static_cast<std::size_t>(args[j])] != 0;
          if (!earlier) {
            std::size_t flat = 0;
            for (std::size_t i = 0; i < m; ++i) flat += static_cast<std::size_t>(args[i]) * stride[i];
            visit(k, shape, flat);
          }
          // Odometer over the arguments other than `at`, the last running fastest.
          std::size_t i = m;
          while (i-- > 0) {
            if (i == at) continue;
            if (++args[i] < shape.radix[i]) break;
            args[i] = 0;
          }
          if (i == static_cast<std::size_t>(-1)) break;
        }
      }
    }
  }
  return finish(n);
}

template <class Scene>
class Semantics {
 public:
  Semantics(const SemanticBinding<Scene>& binding, SemanticOptions options = {})
      : binding_(binding), core_(binding.mln, binding.constant_type, predicates_of(binding), options) {}

  std::shared_ptr<const Outcome> evaluate(const Scene& scene, std::size_t n) {
    return core_.run(n, true, {}, nullptr, truth(scene));
  }
  // Relative to the previous evaluate / update call (same n): `changed` must name every
  // constant whose atoms may differ from that call's scene.
  std::shared_ptr<const Outcome> update(const Scene& scene, std::size_t n, std::span<const std::int32_t> changed) {
    return core_.run(n, false, changed, nullptr, truth(scene));
  }
  // Relative to `base`, the outcome of the scene before the change (same n): the usual form
  // in a sampler, where `base` is the current state's outcome and rejected proposals leave it.
  std::shared_ptr<const Outcome> update(const Scene& scene, std::size_t n, std::span<const std::int32_t> changed,
                                        const Outcome& base) {
    return core_.run(n, false, changed, &base, truth(scene));
  }
  std::shared_ptr<const Outcome> empty_evidence(std::size_t n) { return core_.empty_evidence(n); }
  double value(const Outcome& o, std::int32_t predicate, std::span<const std::int32_t> args) const {
    return core_.value(o, predicate, args);
  }
  // Σ over the conditional priors and their bindings whose conditions hold of the term
  // (0 for an impossible outcome).
  double conditional_priors(const Scene& scene, const Outcome& o) const;
  nlohmann::ordered_json queries_json(const Outcome& o, const std::vector<std::string>& names) const {
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

template <class Scene>
double Semantics<Scene>::conditional_priors(const Scene& scene, const Outcome& o) const {
  if (!o.possible) return 0.0;
  double total = 0.0;
  std::vector<std::int32_t> binding, radix;
  for (const ConditionalPrior<Scene>& prior : binding_.conditional_priors) {
    const std::size_t k = prior.var_types.size();
    radix.clear();
    std::size_t count = 1;
    for (const std::int32_t t : prior.var_types) {
      radix.push_back(static_cast<std::int32_t>(core_.constants_of(t, o.constants)));
      count *= static_cast<std::size_t>(radix.back());
    }
    binding.assign(k, 0);
    for (std::size_t flat = 0; flat < count; ++flat) {
      if (flat != 0)
        for (std::size_t i = k; i-- > 0;) {
          if (++binding[i] < radix[i]) break;
          binding[i] = 0;
        }
      bool pass = true;
      for (const Condition& c : prior.conditions) {
        pass = core_.holds(o, c, binding);
        if (!pass) break;
      }
      if (pass) total += prior.eval(scene, binding.data());
    }
  }
  return total;
}

}  // namespace ksmc::runtime::domain
