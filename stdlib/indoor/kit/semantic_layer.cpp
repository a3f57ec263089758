#include "stdlib/indoor/kit/semantic_layer.h"

#include <algorithm>
#include <cmath>

#include "runtime/domain/labels.h"

namespace ksmc::stdlib::indoor::kit {

namespace dom = runtime::domain;

namespace {
dom::SemanticOptions options_for(const KitPlan& plan, std::uint64_t seed) {
  dom::SemanticOptions o;
  o.seed = seed;
  o.log_z = plan.mln_prior;
  return o;
}
}  // namespace

SemanticLayer::SemanticLayer(const blocks::Binding& binding, const KitPlan& plan, double resolution,
                             const ClassGrid* map, std::uint64_t seed, const cv::Mat1f* free_distance)
    : binding_(binding),
      plan_(plan),
      resolution_(resolution),
      map_(map),
      free_distance_(free_distance),
      sem_(binding, options_for(plan, seed)) {}

SemanticResult SemanticLayer::evaluate(const World& w) {
  const blocks::Scene scene(w, resolution_, map_, free_distance_);
  return finish(scene, sem_.evaluate(scene, w.units().size()));
}

SemanticResult SemanticLayer::evaluate(const World& w, const SemanticResult& base, std::span<const UnitId> changed) {
  const auto units = w.units();
  const bool same = base.outcome != nullptr && base.ids.size() == units.size() &&
                    std::equal(units.begin(), units.end(), base.ids.begin(), [](const Unit& u, UnitId id) { return u.id == id; });
  if (!same) return evaluate(w);
  std::vector<std::int32_t> idx;
  const auto enumerated = static_cast<std::int32_t>(sem_.core().enumerated());
  for (UnitId id : changed) {
    const auto it = std::lower_bound(base.ids.begin(), base.ids.end(), id);
    if (it != base.ids.end() && *it == id) idx.push_back(enumerated + static_cast<std::int32_t>(it - base.ids.begin()));
  }
  const blocks::Scene scene(w, resolution_, map_, free_distance_);
  return finish(scene, sem_.update(scene, units.size(), idx, *base.outcome));
}

SemanticResult SemanticLayer::finish(const blocks::Scene& scene, std::shared_ptr<const dom::Outcome> outcome) {
  const World& w = scene.world();
  const std::size_t n = w.units().size();
  SemanticResult r;
  r.outcome = std::move(outcome);
  const dom::Outcome& o = *r.outcome;
  for (const Unit& u : w.units()) r.ids.push_back(u.id);
  const std::size_t enumerated = sem_.core().enumerated();  // constants before the units
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t arg[1] = {static_cast<std::int32_t>(enumerated + i)};
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
      const double term = cp.eval(scene, c.data());
      r.log_terms += term;
      r.strained += term < -2.0 ? 1 : 0;
      PriorBinding b{p, {}};
      for (std::size_t v = 0; v < c.size(); ++v) {
        const auto k = static_cast<std::size_t>(c[v]);
        const bool unit = cp.var_types[v] == binding_.constant_type && k >= enumerated;
        b.units.push_back(unit ? r.ids[k - enumerated] : PriorBinding::kConstant + k);
      }
      r.terms.push_back(std::move(b));
    }
  }
  if (plan_.mln_prior) {
    const double base = sem_.empty_evidence(n)->log_z;
    r.log_mln = o.log_z - (std::isfinite(base) ? base : 0.0);
  }
  return r;
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
