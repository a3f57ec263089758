// Exact inference, one connected component at a time: by enumeration (below) or by
// variable elimination on a junction tree (elimination.h), whichever the component's
// estimated cost favours (plan_exact).
//
// Each component is enumerated with a loopless reflected mixed-radix Gray code
// (a free atom is a binary digit, an exactly-one block one k-ary digit), so each
// step changes one atom (or moves one block's true atom) and clause satisfaction
// counts, the soft log-weight and the number of violated hard clauses are updated
// incrementally. Marginals are accumulated lazily (O(1) per step). One-atom
// components are solved in closed form. log Z = constant + sum of component log Z.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "runtime/mln/components.h"
#include "runtime/mln/elimination.h"
#include "runtime/mln/ground_network.h"
#include "runtime/mln/inference_result.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::mln {

struct ExactOptions {
  // Largest component enumerated: its state count must be <= 2^max_component_bits.
  std::int32_t max_component_bits = 24;
  // Variable elimination: allowed when no cluster table exceeds max_cluster_entries and
  // all of them together stay within max_elimination_entries.
  bool use_elimination = true;
  double max_cluster_entries = 1 << 20;
  double max_elimination_entries = 1 << 24;
};

struct ComponentResult {
  std::vector<double> marginals;   // local atom ids
  double log_z = 0.0;              // without the network constant
  std::vector<std::uint8_t> mode;  // a most probable state (first found on ties)
  double mode_log_weight = 0.0;    // its log-weight, without the network constant
};

// log2 of the number of states of a component (blocks count log2 k, atoms 1).
double component_state_bits(const GroundNetwork& net, const Component& comp);

// Enumerates the whole network as one piece (no size check); throws MlnError if no
// state satisfies the hard clauses and blocks.
ComponentResult enumerate_network(const GroundNetwork& net);

// Exact marginals and log Z of the whole network. Throws MlnError naming the
// component size and its predicates when a component is too large for both solvers.
InferenceResult exact_inference(const GroundNetwork& net, const ExactOptions& options = {});

// How one component is solved exactly, and what it costs.
struct ExactPlan {
  enum class Solver { Enumerate, Eliminate, TooLarge } solver = Solver::Enumerate;
  double bits = 0.0;          // log2 of the component's state count
  EliminationPlan elimination;  // when solver == Eliminate
};

// Picks enumeration or elimination for a component from their estimated costs
// (2^bits steps against the total junction-tree table size); TooLarge when neither
// fits the options' limits. Components of at most 10 bits are enumerated unplanned.
ExactPlan plan_exact(const GroundNetwork& net, const Component& comp, const ExactOptions& options);

// Counts of the solvers used, for InferenceResult::method.
struct ExactSummary {
  std::int32_t enumerated = 0, eliminated = 0, sampled = 0, width = 0;
  void add(const ExactPlan& plan);
  // "exact:enum 3, elim 1 (width 4)"; with sampled components "auto:enum 3, mcsat 1".
  std::string describe() const;
};

// Solves the given components of `net` exactly, each as `plans` says (plans[i] for
// comps[i], none TooLarge): writes their atoms' marginals into `marginals` (global
// ids, sized num_atoms) and, if `mode` is given, a most probable state into it, and if
// `clause_prob` is given (sized num_clauses), the probability that each of their clauses
// is satisfied; returns the sum of their log Z (without the network constant).
double solve_components(const GroundNetwork& net, std::span<const Component> comps,
                        std::span<const ExactPlan> plans, std::vector<double>& marginals,
                        std::vector<std::uint8_t>* mode = nullptr, std::vector<double>* clause_prob = nullptr);

// Exact inference plus, per clause, the probability that it is satisfied (hard clauses:
// 1 up to rounding): d log Z / d weight(c), the expected clause counts of the gradient
// of a log-likelihood.
InferenceResult exact_clause_probabilities(const GroundNetwork& net, std::vector<double>& clause_prob,
                                           const ExactOptions& options = {});

// Solves the given components of `net` exactly (planning each with default options,
// no size check): writes their atoms' marginals into `marginals` (global ids, sized
// num_atoms) and returns the sum of their log Z (without the network constant).
double exact_components(const GroundNetwork& net, std::span<const Component> comps, std::vector<double>& marginals);

// Exact MAP: the most probable state, assembled from per-component modes (same size
// limit as exact_inference).
MapResult exact_map(const GroundNetwork& net, const ExactOptions& options = {});

// The message used when a component is too large (shared with the auto mode).
std::string too_large_message(const GroundNetwork& net, const Component& comp,
                              const ExactOptions& options);

}  // namespace ksmc::runtime::mln
