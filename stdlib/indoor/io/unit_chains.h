// Units that continue each other: rectangles the chain placed end to end whose facing sides
// coincide, with no wall between them, as a corridor drawn in straight pieces or a hall cut in
// two across by furniture. segmentation.cpp joins them into one segment: a corridor 1.1 m wide
// in pieces meets its next piece over its width, no wider than a door, and the corridor join
// cannot tell that from a doorway; two pieces of a hall are each too large for the join of two
// units in one open space.
#pragma once

#include <utility>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// Two units whose facing sides coincide: anti-parallel (within kSideAngleDeg), at most `gap`
// cells apart along their normal, and each covering at least kSideCover of the longer of the
// two sides. `side`: the longer side's length in cells; `from`, `to`: the seam, the part of the
// two sides that overlaps, on the line midway between them. a < b (unit ids).
struct SideMatch {
  int a = 0;
  int b = 0;
  double side = 0.0;
  Point2 from, to;
};

constexpr double kSideAngleDeg = 2.0;
constexpr double kSideCover = 0.85;

// All such pairs of `units`, ordered by (a, b); units with a degenerate quad never match.
std::vector<SideMatch> matching_sides(const std::vector<UnitResult>& units, double gap);

constexpr double kSeamGap = 2.0;     // cells between the facing sides of two units that continue each other
constexpr double kSeamBeside = 4.0;  // cells: the lines either side of the seam it is compared with
constexpr double kFreeSeam = 0.75;   // of the cells along the seam free
constexpr double kOpenSeam = 0.9;    // of the free cells beside the seam free on it

// The pairs of `units` that continue each other on `grid`: matching_sides within kSeamGap whose
// seam is open: of the cells on the line midway between the two sides (one sample per cell), at
// least kFreeSeam free, and at least kOpenSeam as many as on the more open of the two lines
// kSeamBeside cells either side of it. A wall with a door narrows the seam (a 0.9 m door in a
// 1.1 m corridor leaves 82 % of it); furniture or a jagged wall face runs on beside it.
// Ordered by (a, b).
std::vector<std::pair<int, int>> continued_units(const ClassGrid& grid, const std::vector<UnitResult>& units);

}  // namespace ksmc::stdlib::indoor::io
