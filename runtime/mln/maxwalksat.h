// MAP inference by MaxWalkSAT (Kautz, Selman & Jiang 1997) on the ground network.
//
// The objective is lexicographic: first the number of violated hard clauses, then
// the summed |w| of soft clauses in the wrong state (unsatisfied positive-weight or
// satisfied negative-weight clauses); hard clauses thus weigh more than all soft ones
// together. Blocks are moved as one variable. Deterministic for a seed.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/mln/ground_network.h"
#include "runtime/mln/local_state.h"
#include "runtime/mln/rng.h"

namespace ksmc::runtime::mln {

struct MapOptions {
  std::int64_t max_flips = 100000;  // per try
  std::int32_t tries = 4;           // random restarts
  std::int64_t stall_flips = 0;     // end a try after this many flips without improvement;
                                    // 0 = 1000 + 20 x clauses
  double noise = 0.3;               // probability of a random (not greedy) move
  std::uint64_t seed = 1;
};

struct MapResult {
  std::vector<std::uint8_t> state;  // one value per atom
  double log_weight = 0.0;          // network log-weight of `state` (incl. constant)
  bool feasible = false;            // all hard clauses and blocks satisfied
  std::int64_t flips = 0;
};

MapResult max_walksat(const GroundNetwork& net, const MapOptions& options = {});

// One WalkSAT step on `state`'s bad clauses: picks a random bad clause and makes one of
// its literals right (greedy by lexicographic delta, or random with prob. `noise`).
// Returns false if there is no bad clause.
bool walksat_step(LocalState& state, Rng& rng, double noise);

// A state satisfying every hard clause and block, found by WalkSAT on the hard clauses
// from random starts. Throws MlnError naming the unsatisfied rules when none is found.
std::vector<std::uint8_t> find_feasible_state(const GroundNetwork& net, const Occurrences& occ, Rng& rng,
                                              std::int64_t max_flips = 200000);

}  // namespace ksmc::runtime::mln
