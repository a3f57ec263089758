// Classified map C_M (seed eq. 3.7) of maps that paint the outside of the building black.
// Eq. 3.7 classifies by intensity only, so a solid black region reads as "occupied" over its
// whole area, while a range sensor only ever observes the surface of an obstacle. No world W
// can predict such an area (C_W is wall only in a one-cell band inside units, eq. 3.8), so
// those cells are misses for every world: on lab_ipa.png 76 % of the map is occupied farther
// than 0.5 m from any free cell, which caps K(W,M) at 0.24 whatever the units are.
// unexplain_solid_interior() reclassifies occupied cells farther than `depth` cells (Euclidean)
// from every free cell as unexplained (1): the surface layer of every obstacle, i.e. every
// wall up to 2 * depth thick, stays occupied. depth <= 0 leaves the grid unchanged.
#pragma once

#include <cstddef>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

// Returns the number of cells changed from Occupied to Unknown.
std::size_t unexplain_solid_interior(ClassGrid& grid, double depth_cells);

}  // namespace ksmc::stdlib::indoor::io
