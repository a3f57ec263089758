// Units the map does not support, removed after the run when the posterior says so.
//
// A unit without a door that the chain made by SPLIT or SHRINK / DILATE (a strip or a small
// rectangle inside a room, on a wall or in a doorway) cannot leave the chain: REMOVE's reverse
// is ADD, whose probability of proposing a rectangle no detector proposes is 0, and MERGE joins
// only units that tile a rectangle. So the chain's best state keeps them, whatever they cost.
// remove_unsupported_units is a local search on the chain's own target after the run: it
// removes a door-less unit when the world without it has a higher log posterior (likelihood,
// weak prior and knowledge), one unit at a time, until no removal raises it. The output is the
// better of the two states under that one target; a unit the map supports stays.
#pragma once

#include <vector>

#include "stdlib/indoor/kit/indoor_model.h"

namespace ksmc::stdlib::indoor::kit {

// The units of `w` with no door, smallest first (ties by id).
std::vector<UnitId> doorless_units(const World& w);

struct RemovedUnits {
  std::vector<UnitId> removed;      // in removal order
  double log_posterior_before = 0.0;
  double log_posterior_after = 0.0;
};

// Removes door-less units from `m`'s current state while each removal raises the log posterior.
RemovedUnits remove_unsupported_units(IndoorModel& m);

}  // namespace ksmc::stdlib::indoor::kit
