// Exact inference by enumeration, one connected component at a time.
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
#include <vector>

#include "runtime/mln/components.h"
#include "runtime/mln/ground_network.h"
#include "runtime/mln/inference_result.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::mln {

struct ExactOptions {
  // Largest component enumerated: its state count must be <= 2^max_component_bits.
  std::int32_t max_component_bits = 24;
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
// component size and its predicates when a component exceeds the limit.
InferenceResult exact_inference(const GroundNetwork& net, const ExactOptions& options = {});

// Enumerates the given components of `net` in place (no size check): writes their
// atoms' marginals into `marginals` (global ids, sized num_atoms) and returns the sum
// of their log Z (without the network constant).
double exact_components(const GroundNetwork& net, std::span<const Component> comps, std::vector<double>& marginals);

// Exact MAP: the most probable state, assembled from per-component modes (same size
// limit as exact_inference).
MapResult exact_map(const GroundNetwork& net, const ExactOptions& options = {});

// The message used when a component is too large (shared with the auto mode).
std::string too_large_message(const GroundNetwork& net, const Component& comp,
                              const ExactOptions& options);

}  // namespace ksmc::runtime::mln
