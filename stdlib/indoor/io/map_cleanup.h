// What the indoor binary does to the loaded classes before it fits a world: clear_specks
// (specks.h), then unexplain_solid_interior (solid_interior.h). world.json records it as
// map.cleanup, so that ksmc-render-world redraws a run's segmentation, overlay and labels over the
// map the run saw, not over the raw one: the specks the run cleared change the walls the
// segmentation's post-steps see (Freiburg79_scan, seed 1: R 93.5 redrawn over the raw map, 91.5
// in the run).
#pragma once

#include <cstddef>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

struct MapCleanup {
  int speck_cells = 0;             // clear_specks' max_cells; 0: none
  double solid_depth_cells = 0.0;  // unexplain_solid_interior's depth; 0: none
};

struct CleanupCounts {
  std::size_t specks_cleared = 0;     // cells Occupied -> Free
  std::size_t solid_unexplained = 0;  // cells Occupied -> Unknown
};

CleanupCounts apply_cleanup(ClassGrid& grid, const MapCleanup& cleanup);

}  // namespace ksmc::stdlib::indoor::io
