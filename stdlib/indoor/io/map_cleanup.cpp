#include "stdlib/indoor/io/map_cleanup.h"

#include "stdlib/indoor/io/solid_interior.h"
#include "stdlib/indoor/io/specks.h"

namespace ksmc::stdlib::indoor::io {

CleanupCounts apply_cleanup(ClassGrid& grid, const MapCleanup& cleanup) {
  CleanupCounts n;
  n.specks_cleared = clear_specks(grid, cleanup.speck_cells);
  n.solid_unexplained = unexplain_solid_interior(grid, cleanup.solid_depth_cells);
  return n;
}

}  // namespace ksmc::stdlib::indoor::io
