// Door candidates for ALLOCATE (detect::detect_doors) with a per-pair cache. The detector's
// result for a pair of units depends only on the two rectangles (and the map), and its full
// output is the concatenation of the pairs' outputs in (unit_a, unit_b) order, each sorted by
// position. So the refresh recomputes only the pairs in which a unit changed since it was last
// seen, and pairs whose rectangles are too far apart for their wall bands to meet are skipped
// without running the detector. The result is identical to detect_doors on all units.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/kernels.h"

namespace ksmc::stdlib::indoor::kit {

class DoorCandidateCache {
 public:
  explicit DoorCandidateCache(detect::DoorParams params, std::size_t max_pairs = 20000)
      : params_(params), max_pairs_(max_pairs) {}

  // Same candidates, in the same order, as to_door_candidates(detect_doors(grid, units, params)).
  // The grid is validated (an O(map) scan) once per grid buffer, not once per pair.
  std::vector<CandidateDoor> candidates(const ClassGrid& grid, const std::vector<OrientedRect>& units);

  std::size_t detector_calls() const { return calls_; }

 private:
  using Key = std::array<double, 10>;
  detect::DoorParams params_;
  std::size_t max_pairs_;
  std::size_t calls_ = 0;
  bool checked_ = false;
  const unsigned char* checked_grid_ = nullptr;
  std::map<Key, std::vector<CandidateDoor>> pairs_;
};

}  // namespace ksmc::stdlib::indoor::kit
