// Classified map C_M (seed eq. 3.7) of SLAM maps that keep specks: single occupied cells in open
// floor where a person walked past or a beam came back early. Eq. 3.7 reads each as a wall, so
// every rule that asks whether two units are separated by a wall sees one wherever a speck lies
// on their join: with 1 % of the free cells speckled, office_e's ring corridor and
// Freiburg52_scan's corridor came out in pieces (docs/indoor_transforms.md, "Speckled maps").
// clear_specks() reads as free every 8-connected occupied region that fits in a square of
// `max_cells` cells, whose every neighbour is free, and that lies farther than 2 * max_cells
// from every larger occupied region: a speck in open floor. A wall end, a pillar or furniture
// wider than that, a dot near a wall (a fragment of a thin wall drawn broken, or of a jagged
// scanned one), and anything touching unexplored or unexplained cells or the map's edge, stays
// occupied. max_cells < 1 leaves the grid unchanged.
#pragma once

#include <cstddef>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

// Returns the number of cells changed from Occupied to Free.
std::size_t clear_specks(ClassGrid& grid, int max_cells);

}  // namespace ksmc::stdlib::indoor::io
