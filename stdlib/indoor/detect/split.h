// SPLIT proposals (seed §3.5.2, eq. 3.18, Fig. 3.15): Hough segments of the wall edges
// inside a unit (its own walls excluded by a margin), parallel to one of the unit's axes,
// are merged per position and extended to the two opposite walls they cut. Weight = the
// length of wall the segments cover (eq. 3.18). Only cuts that cross two opposite walls are
// proposed, as in the seed.
#pragma once

#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/hough.h"
#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

struct SplitParams {
  HoughParams hough{1.0, 0.5, 10, 8.0, 2.0};  // shorter walls than WBU: 8 cells (0.4 m)
  double margin = 4.0;              // cells next to the unit's own walls ignored, cells
  double axis_tolerance_deg = 3.0;  // segment direction vs unit axis
  double merge_distance = 3.0;      // parallel segments closer than this are one cut, cells
  double min_part = 5.0;            // each side of the cut at least this wide, cells
  double min_weight = 8.0;          // covered length a cut needs, cells
};

// Split lines of `unit`, strongest first (ties by position). Endpoints lie on the unit's
// boundary. Throws std::invalid_argument on a bad grid or a degenerate unit.
std::vector<SplitLine> detect_split_lines(const ClassGrid& grid, const OrientedRect& unit,
                                          const SplitParams& params = {}, GridCheck check = GridCheck::Full);

}  // namespace ksmc::stdlib::indoor::detect
