// RPB detector (seed §3.5.2, Fig. 3.14): where the robot is must be free space, so a unit
// is grown around the robot position, in the given frame, one cell per side and round,
// until every side has reached a wall (or unknown space, or the size cap). Its sides end on
// the blocking cells, i.e. on the walls, like WBU candidates.
#pragma once

#include <optional>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/types.h"
#include "stdlib/indoor/detect/wall_score.h"

namespace ksmc::stdlib::indoor::detect {

struct RpbParams {
  double frame_deg = 0.0;          // orientation of the unit (e.g. the dominant orientation)
  double min_side = 10.0;          // smaller results are not proposed, cells (0.5 m)
  double max_half_extent = 100.0;  // a side stops this far from the robot, cells (5 m)
  double max_blocked = 0.05;       // a side stops when more than this fraction of its next strip
  int min_blocked_cells = 2;       //   (and at least this many cells) is occupied or unknown
  WallScoreParams wall{};          // for the weight
  double weight_floor = 0.05;      // weight = max(eq. 3.10, floor)
};

// nullopt when the robot cell is outside the map or not free, or the grown unit is smaller
// than min_side. Throws std::invalid_argument on a bad grid.
std::optional<UnitCandidate> detect_rpb_unit(const ClassGrid& grid, Point2 robot, const RpbParams& params = {});

}  // namespace ksmc::stdlib::indoor::detect
