// The semantic half of the indoor model (seed §3.8) over the shared evaluator
// runtime::domain::Semantics: the generated extractors give the evidence of a world, Markov
// logic gives the marginals (cached by evidence), and from them the unit types (the type
// group of KitPlan, argmax with ties to the first member), the bindings of the conditional
// priors whose conditions hold and the knowledge part of log p(W): the terms of those
// bindings plus, with `prior mln`, log Z(evidence) - log Z(no evidence atom holds). All of
// it is a function of the world alone, so the model's target is one fixed posterior; the
// sampler re-evaluates it on every proposal, re-extracting only the atoms of the units a move
// touched (IndoorModel).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/domain/semantics.h"
#include "stdlib/indoor/blocks.h"
#include "stdlib/indoor/kit/plan.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

// One binding of a conditional prior whose conditions held: the prior (index into the
// binding's conditional_priors) and, per variable, the unit id (a run-time constant) or, for
// an enumerated constant, kConstant + its index.
struct PriorBinding {
  static constexpr std::uint64_t kConstant = std::uint64_t{1} << 32;
  std::size_t prior = 0;
  std::vector<std::uint64_t> units;
  bool operator==(const PriorBinding&) const = default;
};

struct SemanticResult {
  std::vector<UnitId> ids;                      // the units in world order at evaluation
  std::vector<std::vector<double>> type_probs;  // per unit, per KitPlan::type_predicates entry
  std::vector<int> type;                        // per unit: index of the most probable type; -1 without types
  std::vector<PriorBinding> terms;              // conditional prior bindings that hold
  std::shared_ptr<const runtime::domain::Outcome> outcome;
  double log_terms = 0.0;  // Σ of the terms of `terms` on the world
  std::size_t strained = 0;  // bindings whose term is below -2 (beyond 2 sd for a gaussian)
  double log_mln = 0.0;    // `prior mln`: log Z(evidence) - log Z(no evidence); -inf when impossible
  bool possible() const { return outcome == nullptr || outcome->possible; }
  double log_knowledge() const { return possible() ? log_terms + log_mln : -std::numeric_limits<double>::infinity(); }
};

class SemanticLayer {
 public:
  // `free_distance`: free_distance(*map) (stdlib/indoor/free_distance.h), the field geom.hollow
  // reads; nullptr (or empty): no unit is hollow. Both pointers must outlive the layer.
  SemanticLayer(const blocks::Binding& binding, const KitPlan& plan, double resolution, const ClassGrid* map,
                std::uint64_t seed, const cv::Mat1f* free_distance = nullptr);

  SemanticResult evaluate(const World& w);
  // The same, relative to `base` (the result of a world with the same units, ids in the same
  // order): only atoms with an argument in `changed` are re-extracted. Falls back to a full
  // evaluation when the unit ids differ.
  SemanticResult evaluate(const World& w, const SemanticResult& base, std::span<const UnitId> changed);

  // The marginal of every ground query atom, units named u<id> ({"Room": {"u3": 0.91}}).
  nlohmann::ordered_json queries_json(const SemanticResult& r) const;
  // The evidence of `r` as an Alchemy .db (constants u<id>).
  std::string evidence_db(const SemanticResult& r) const;
  // Names of the type predicates (KitPlan::type_predicates order).
  std::vector<std::string> type_names() const;
  const runtime::domain::SemanticStats& stats() const { return sem_.core().stats(); }

 private:
  std::vector<std::string> names(const SemanticResult& r) const;
  SemanticResult finish(const blocks::Scene& scene, std::shared_ptr<const runtime::domain::Outcome> outcome);

  const blocks::Binding& binding_;
  const KitPlan& plan_;
  double resolution_;
  const ClassGrid* map_;
  const cv::Mat1f* free_distance_;
  runtime::domain::Semantics<blocks::Scene> sem_;
};

}  // namespace ksmc::stdlib::indoor::kit
