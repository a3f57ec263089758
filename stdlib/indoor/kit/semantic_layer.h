// The semantic half of the indoor model (seed §3.8) over the shared evaluator
// runtime::domain::Semantics: the generated extractors give the evidence of a world, Markov
// logic gives the marginals (cached by evidence), and from them the unit types (the type
// group of KitPlan, argmax with ties to the first member) and the bindings of the conditional
// priors whose conditions hold. The bindings are kept as unit ids, so their terms can be
// summed on later worlds until the next refresh (IndoorModel).
#pragma once

#include <cstdint>
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
// binding's conditional_priors) and, per variable, the unit id.
struct PriorBinding {
  std::size_t prior = 0;
  std::vector<UnitId> units;
  bool operator==(const PriorBinding&) const = default;
};

struct SemanticResult {
  std::vector<UnitId> ids;                      // the units in world order at evaluation
  std::vector<std::vector<double>> type_probs;  // per unit, per KitPlan::type_predicates entry
  std::vector<int> type;                        // per unit: index of the most probable type; -1 without types
  std::vector<PriorBinding> terms;              // conditional prior bindings that hold
  std::shared_ptr<const runtime::domain::Outcome> outcome;
};

class SemanticLayer {
 public:
  SemanticLayer(const blocks::Binding& binding, const KitPlan& plan, double resolution, const ClassGrid* map,
                std::uint64_t seed);

  SemanticResult evaluate(const World& w);
  // Σ of the terms of `terms` on `w`; a binding with a unit no longer in `w` adds nothing.
  double log_prior(const World& w, const std::vector<PriorBinding>& terms) const;

  // The marginal of every ground query atom, units named u<id> ({"Room": {"u3": 0.91}}).
  nlohmann::ordered_json queries_json(const SemanticResult& r) const;
  // The evidence of `r` as an Alchemy .db (constants u<id>).
  std::string evidence_db(const SemanticResult& r) const;
  // Names of the type predicates (KitPlan::type_predicates order).
  std::vector<std::string> type_names() const;
  const runtime::domain::SemanticStats& stats() const { return sem_.core().stats(); }

 private:
  std::vector<std::string> names(const SemanticResult& r) const;

  const blocks::Binding& binding_;
  const KitPlan& plan_;
  double resolution_;
  const ClassGrid* map_;
  runtime::domain::Semantics<blocks::Scene> sem_;
};

}  // namespace ksmc::stdlib::indoor::kit
