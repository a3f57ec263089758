// After the run: a local search on the chain's own target, from the chain's best state.
//
// Changes the chain cannot make, or cannot make with every domain's sources, whatever they
// would gain:
//  - removing a door-less unit that no detector proposes, unless the domain declares
//    move.uniform_rect (without it REMOVE's reverse, ADD, proposes such a rectangle with
//    probability 0): strips inside rooms, squares on walls (unsupported_units.h);
//  - merging two units that nearly tile a rectangle but not exactly (MERGE needs an exact
//    tiling), or that a door joins where move.seam_doors gives MERGE no reverse (no such
//    source, or a cut that is not across a corridor): a corridor in pieces with a door between
//    each two (merged_units.h);
//  - splitting a unit along a wall that runs through it, with a door in the wall's opening or
//    without: a hall over several rooms whose walls the chain's split lines miss
//    (split_units.h).
// Each candidate is scored as a proposal is, incrementally, on the chain's target (likelihood,
// weak prior and knowledge: IndoorModel::improve). The first candidate with a higher log
// posterior is taken and the search starts again, until none is higher. The result is the better state under the one
// target; a unit or a wall the map supports stays.
#pragma once

#include <vector>

#include "stdlib/indoor/kit/indoor_model.h"

namespace ksmc::stdlib::indoor::kit {

struct AfterRunResult {
  std::vector<UnitId> removed;                      // in order
  std::vector<std::pair<UnitId, UnitId>> merged;    // in order
  std::vector<UnitId> split;                        // in order
  double log_posterior_before = 0.0;
  double log_posterior_after = 0.0;
};

AfterRunResult improve_after_run(IndoorModel& m);

}  // namespace ksmc::stdlib::indoor::kit
