#include "runtime/mln/incremental.h"

#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "runtime/mln/components.h"
#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {
namespace {

// The component's variables named by query index: its atoms, then each block's atoms.
std::vector<std::int64_t> variable_key(const Grounding& g, const Component& comp) {
  const auto& q = g.index.query_of_atom;
  std::vector<std::int64_t> key;
  key.reserve(comp.atoms.size() * 2 + comp.blocks.size() + 1);
  for (AtomId a : comp.atoms) key.push_back(q[a]);
  for (std::int32_t b : comp.blocks) {
    key.push_back(-1);
    for (AtomId a : g.network.block(b)) key.push_back(q[a]);
  }
  return key;
}

// Variables plus every clause (weight bits, then literals by query index).
std::vector<std::int64_t> content_key(const Grounding& g, const Component& comp, std::vector<std::int64_t> key) {
  const auto& net = g.network;
  const auto& q = g.index.query_of_atom;
  for (std::int32_t c : comp.clauses) {
    key.push_back(-2);
    key.push_back(std::bit_cast<std::int64_t>(net.weight(c)));
    for (Lit l : net.clause(c)) key.push_back(q[lit_atom(l)] * 2 + (lit_negated(l) ? 1 : 0));
  }
  return key;
}

}  // namespace

IncrementalInference::IncrementalInference(const Program& program, const Domain& domain, const Evidence& evidence,
                                           InferenceOptions options, Grounder grounder)
    : program_(program), domain_(domain), evidence_(evidence), options_(std::move(options)),
      grounder_(std::move(grounder)) {
  if (options_.method != Method::Auto && options_.method != Method::Exact)
    throw MlnError("incremental inference needs the exact or auto method");
  if (!grounder_) {
    grounder_ = [this](const Domain& d, const Evidence& ev) { return ground(program_, d, ev); };
  }
  run();
}

const InferenceResult& IncrementalInference::update(std::span<const EvidenceChange> changes) {
  for (const auto& ch : changes) {
    if (ch.predicate < 0 || ch.predicate >= static_cast<std::int32_t>(program_.predicates.size()))
      throw MlnError("incremental inference: no predicate with id " + std::to_string(ch.predicate));
    const auto& pred = program_.predicates[ch.predicate];
    if (ch.args.size() != pred.arg_types.size())
      throw MlnError("incremental inference: " + pred.name + " takes " + std::to_string(pred.arg_types.size()) +
                     " arguments, the change gives " + std::to_string(ch.args.size()));
    for (std::size_t i = 0; i < ch.args.size(); ++i) {
      if (ch.args[i] < 0 || ch.args[i] >= domain_.size(pred.arg_types[i]))
        throw MlnError("incremental inference: argument " + std::to_string(i + 1) + " of " + pred.name +
                       " is not a constant of its type");
    }
    if (ch.value == Evidence::kUnknown && !pred.query)
      throw MlnError("incremental inference: evidence atom of " + pred.name + " cannot be unknown (closed world)");
    evidence_.set_flat(ch.predicate, evidence_.flat_index(ch.predicate, ch.args), ch.value);
  }
  run();
  return result_;
}

void IncrementalInference::run() {
  grounding_ = grounder_(domain_, evidence_);
  const auto& net = grounding_.network;
  const auto comps = split_components(net);
  std::map<std::vector<std::int64_t>, Cached> results;
  std::map<std::vector<std::int64_t>, CachedPlan> plans;
  stats_ = {};
  stats_.components = static_cast<std::int32_t>(comps.size());
  InferenceResult r;
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  r.log_z = net.constant();
  r.log_z_exact = true;
  ExactSummary summary;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    const auto& comp = comps[i];
    auto vkey = variable_key(grounding_, comp);
    auto ckey = content_key(grounding_, comp, vkey);
    Cached entry;
    if (auto it = results_.find(ckey); it != results_.end()) {
      entry = std::move(it->second);
      results_.erase(it);
      ++stats_.reused;
    } else {
      ++stats_.solved;
      ExactPlan plan;
      plan.bits = component_state_bits(net, comp);
      bool planned = false;
      if (plan.bits > 10.0 && options_.exact.use_elimination) {
        if (auto pit = plans_.find(vkey); pit != plans_.end()) {
          plan.elimination = pit->second.plan;
          if (rebind_plan(net, pit->second.comp, comp, plan.elimination)) {
            plan.solver = ExactPlan::Solver::Eliminate;
            planned = true;
            ++stats_.plans_reused;
          }
        }
      }
      if (!planned) plan = plan_exact(net, comp, options_.exact);
      summary.add(plan);
      InferenceResult part;
      part.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
      part.log_z_exact = true;
      if (plan.solver == ExactPlan::Solver::TooLarge) {
        if (options_.method == Method::Exact) throw MlnError(too_large_message(net, comp, options_.exact));
        entry.log_z = sample_component(net, comp, options_, i, part);
        entry.exact = part.log_z_exact && options_.compute_log_z;
        entry.samples = part.samples;
      } else {
        const Component one[] = {comp};
        const ExactPlan plans_one[] = {plan};
        entry.log_z = solve_components(net, one, plans_one, part.marginals);
      }
      entry.marginals.resize(comp.atoms.size());
      for (std::size_t k = 0; k < comp.atoms.size(); ++k) entry.marginals[k] = part.marginals[comp.atoms[k]];
      if (plan.solver == ExactPlan::Solver::Eliminate) plans[vkey] = {comp, std::move(plan.elimination)};
    }
    if (auto pit = plans_.find(vkey); pit != plans_.end() && !plans.count(vkey)) {
      // unchanged component: keep its plan for a later change, moved to the new ids
      EliminationPlan moved = std::move(pit->second.plan);
      if (rebind_plan(net, pit->second.comp, comp, moved)) plans[vkey] = {comp, std::move(moved)};
    }
    for (std::size_t k = 0; k < comp.atoms.size(); ++k) r.marginals[comp.atoms[k]] = entry.marginals[k];
    r.log_z += entry.log_z;
    r.log_z_exact = r.log_z_exact && entry.exact;
    r.samples = std::max(r.samples, entry.samples);
    results.emplace(std::move(ckey), std::move(entry));
  }
  if (!r.log_z_exact && !options_.compute_log_z) r.log_z = std::numeric_limits<double>::quiet_NaN();
  r.method = "incremental: " + std::to_string(stats_.reused) + " of " + std::to_string(stats_.components) +
             " components reused, re-solved " + summary.describe();
  results_ = std::move(results);
  plans_ = std::move(plans);
  result_ = std::move(r);
}

}  // namespace ksmc::runtime::mln
