#include "stdlib/indoor/kit/semantic_layer.h"

#include <algorithm>

#include "runtime/domain/labels.h"

namespace ksmc::stdlib::indoor::kit {

namespace dom = runtime::domain;

namespace {
dom::SemanticOptions options_for(std::uint64_t seed) {
  dom::SemanticOptions o;
  o.seed = seed;
  return o;
}
}  // namespace

SemanticLayer::SemanticLayer(const blocks::Binding& binding, const KitPlan& plan, double resolution,
                             const ClassGrid* map, std::uint64_t seed)
    : binding_(binding), plan_(plan), resolution_(resolution), map_(map), sem_(binding, options_for(seed)) {}

SemanticResult SemanticLayer::evaluate(const World& w) {
  const blocks::Scene scene(w, resolution_, map_);
  const std::size_t n = w.units().size();
  SemanticResult r;
  r.outcome = sem_.evaluate(scene, n);
  const dom::Outcome& o = *r.outcome;
  for (const Unit& u : w.units()) r.ids.push_back(u.id);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t arg[1] = {static_cast<std::int32_t>(i)};
    std::vector<double> probs;
    for (std::int32_t q : plan_.type_predicates) probs.push_back(sem_.value(o, q, arg));
    r.type.push_back(probs.empty() ? -1 : static_cast<int>(dom::most_probable(probs)));
    r.type_probs.push_back(std::move(probs));
  }
  // The bindings of each conditional prior (every combination of constants of its variables'
  // types) whose conditions all hold in the outcome.
  const auto& priors = binding_.conditional_priors;
  for (std::size_t p = 0; p < priors.size(); ++p) {
    const auto& cp = priors[p];
    std::vector<std::size_t> sizes;
    std::size_t combos = 1;
    for (std::int32_t t : cp.var_types) {
      sizes.push_back(sem_.core().constants_of(t, n));
      combos *= sizes.back();
    }
    std::vector<std::int32_t> c(cp.var_types.size(), 0);
    for (std::size_t flat = 0; flat < combos; ++flat) {
      std::size_t rest = flat;
      for (std::size_t v = cp.var_types.size(); v-- > 0;) {
        c[v] = static_cast<std::int32_t>(rest % sizes[v]);
        rest /= sizes[v];
      }
      const bool holds = std::all_of(cp.conditions.begin(), cp.conditions.end(),
                                     [&](const dom::Condition& cond) { return sem_.core().holds(o, cond, c); });
      if (!holds) continue;
      PriorBinding b{p, {}};
      for (std::int32_t k : c) b.units.push_back(r.ids[static_cast<std::size_t>(k)]);
      r.terms.push_back(std::move(b));
    }
  }
  return r;
}

double SemanticLayer::log_prior(const World& w, const std::vector<PriorBinding>& terms) const {
  if (terms.empty()) return 0.0;
  const blocks::Scene scene(w, resolution_, map_);
  const auto units = w.units();
  double lp = 0.0;
  std::vector<std::int32_t> c;
  for (const PriorBinding& b : terms) {
    c.clear();
    for (UnitId id : b.units) {
      const auto it = std::lower_bound(units.begin(), units.end(), id, [](const Unit& u, UnitId x) { return u.id < x; });
      if (it == units.end() || it->id != id) break;
      c.push_back(static_cast<std::int32_t>(it - units.begin()));
    }
    if (c.size() == b.units.size()) lp += binding_.conditional_priors[b.prior].eval(scene, c.data());
  }
  return lp;
}

std::vector<std::string> SemanticLayer::names(const SemanticResult& r) const {
  std::vector<std::string> out;
  for (UnitId id : r.ids) out.push_back("u" + std::to_string(id));
  return out;
}

nlohmann::ordered_json SemanticLayer::queries_json(const SemanticResult& r) const { return sem_.queries_json(*r.outcome, names(r)); }

std::string SemanticLayer::evidence_db(const SemanticResult& r) const { return sem_.evidence_db(*r.outcome, names(r)); }

std::vector<std::string> SemanticLayer::type_names() const {
  std::vector<std::string> out;
  for (std::int32_t q : plan_.type_predicates) out.push_back(sem_.core().program().predicates[static_cast<std::size_t>(q)].name);
  return out;
}

}  // namespace ksmc::stdlib::indoor::kit
