// Exact inference by variable elimination on a junction tree, one connected component
// at a time: the alternative to enumeration for components that are large but sparse
// (the indoor knowledge base: one block per space unit, linked along the adjacency of a
// nearly planar floor plan).
//
// Variables: every free atom outside a block is a binary variable, every exactly-one
// block one k-ary variable (value j = the block's j-th atom is true), so blocks are
// respected by construction. Each clause is a factor over the variables of its atoms
// (exp(w) when satisfied; a hard clause is 0 when violated). The elimination order is
// greedy min-fill (ties: fewest neighbours, then lowest variable), and it defines the
// junction tree: the cluster of variable v is v plus its neighbours when it is
// eliminated, its parent the cluster of the first-eliminated variable among those
// neighbours. Each clause goes to the cluster of its first-eliminated variable.
//
// Sum-product: an upward pass (messages normalised to max 1, their logs summed into
// log Z) and a downward Hugin pass give every cluster's belief, hence the marginal of
// its variable. Max-product with back-pointers gives a most probable state (MAP).
// Tables are dense (mixed radix over the cluster's variables in ascending id order),
// so the cost is the sum of the cluster table sizes: plan first, then decide.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/mln/components.h"
#include "runtime/mln/ground_network.h"

namespace ksmc::runtime::mln {

struct EliminationPlan {
  // Variables (local ids 0..n-1): atoms of var v are var_atoms[var_offsets[v] ..
  // var_offsets[v+1]) (one for a plain atom, the block's atoms for a block).
  std::vector<std::int32_t> var_offsets;         // empty or starting with 0
  std::vector<AtomId> var_atoms;
  std::vector<std::int32_t> order;               // elimination order (variable ids)
  std::vector<std::vector<std::int32_t>> scope;  // scope[i]: cluster of order[i], ascending var ids
  std::vector<std::int32_t> parent;              // parent cluster (step index), -1 for a root
  std::vector<std::vector<std::int32_t>> clauses;  // global clause ids assigned to cluster i
  std::int32_t width = 0;        // induced width: largest cluster minus one (variables)
  double max_entries = 0.0;      // largest cluster table
  double total_entries = 0.0;    // sum of cluster tables (the cost of one pass)

  std::int32_t num_vars() const { return var_offsets.empty() ? 0 : static_cast<std::int32_t>(var_offsets.size()) - 1; }
  std::int32_t card(std::int32_t v) const {
    const std::int32_t k = var_offsets[v + 1] - var_offsets[v];
    return k == 1 ? 2 : k;
  }
};

// Builds the variables, the min-fill order and the junction tree of one component.
// Stops early (returns a plan with max_entries above `entry_limit`) once a cluster
// exceeds the limit, so planning a hopeless component stays cheap.
EliminationPlan plan_elimination(const GroundNetwork& net, const Component& comp,
                                 double entry_limit = 1e300);

// Moves a plan made for component `from` onto `to`, a component (of `net`) with the same
// variables: from.atoms[k] and to.atoms[k] are the same atom, and blocks match. Assigns
// to's clauses to clusters; returns false (plan unusable) when a clause's variables are
// in no single cluster.
bool rebind_plan(const GroundNetwork& net, const Component& from, const Component& to, EliminationPlan& plan);

// Marginals (written into marg[atom], global ids) and the component's log Z (without
// the network constant). If `mode` is given, also a most probable state of the
// component into (*mode)[atom] and its log-weight into *mode_lw. If `clause_prob` is
// given, the probability that each clause of the component is satisfied goes into
// (*clause_prob)[clause] (global ids; from the calibrated belief of the clause's
// cluster). Throws MlnError if no state satisfies the hard clauses and blocks.
double eliminate_component(const GroundNetwork& net, const Component& comp, const EliminationPlan& plan,
                           std::vector<double>& marg, std::vector<std::uint8_t>* mode = nullptr,
                           double* mode_lw = nullptr, std::vector<double>* clause_prob = nullptr);

}  // namespace ksmc::runtime::mln
