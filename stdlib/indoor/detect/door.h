// Door detector for ALLOCATE (seed §3.5.2, Fig. 3.18), in the seed's four steps:
//  1. every wall of every unit is shortened at both ends and expanded perpendicular to
//     itself into a band (so that bands of one unit do not overlap);
//  2. overlaps of bands of two different units are found by connected components; each
//     overlap localises the part of both walls that caused it;
//  3. that part of each wall is divided into equal segments, each weighted by eq. 3.23-3.25
//     (fraction of free samples; a sample is free only if the wall band is open across its
//     whole thickness); segments above a threshold are verified;
//  4. verified segments closer than a gap threshold are merged on each wall, and the parts
//     found on both walls of the pair become door candidates (on the mid line between the two
//     walls), weighted by eq. 3.23 over the whole door.
#pragma once

#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

struct DoorParams {
  double shorten = 3.0;          // cut from each end of a wall before expanding, cells
  double expand = 3.0;           // half-width of a wall band, cells (0.15 m)
  double max_angle_deg = 10.0;   // walls of a pair must be this parallel
  int min_overlap_cells = 4;     // smaller overlap components are ignored
  double segment_length = 2.0;   // step 3 segment length, cells (0.1 m)
  double verify_weight = 0.6;    // step 3 threshold on eq. 3.23
  double merge_gap = 3.0;        // step 4: verified segments closer than this merge, cells
  double min_door = 6.0;         // shortest door, cells (0.3 m)
  double max_door = 40.0;        // widest door, cells (2 m)
};

// Door candidates between the given units, sorted by (unit_a, unit_b, position). unit_a <
// unit_b index `units`. Throws std::invalid_argument on a bad grid or a degenerate unit.
std::vector<DoorCandidate> detect_doors(const ClassGrid& grid, const std::vector<OrientedRect>& units,
                                        const DoorParams& params = {}, GridCheck check = GridCheck::Full);

}  // namespace ksmc::stdlib::indoor::detect
