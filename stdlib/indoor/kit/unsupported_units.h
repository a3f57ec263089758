// Door-less units: candidates for removal after the run (after_run.h). A unit without a door
// that the chain made by SPLIT or SHRINK / DILATE (a strip inside a room, a square on a wall)
// cannot leave the chain: REMOVE's reverse is ADD, whose probability of proposing a rectangle
// no detector proposes is 0, and MERGE joins only units that tile a rectangle.
#pragma once

#include <vector>

#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

// The units of `w` with no door, smallest first (ties by id).
std::vector<UnitId> doorless_units(const World& w);

// The move that removes unit `id` (a unit of `w` with no door).
Move removal(const World& w, UnitId id);

}  // namespace ksmc::stdlib::indoor::kit
