// Units that continue each other: rectangles the chain placed end to end, meeting over the
// whole free passage between them with no wall, as a corridor drawn in straight pieces or a hall
// cut in two across by furniture. segmentation.cpp joins them into one segment: a narrow corridor
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

// Two units whose facing sides meet: anti-parallel (within kSideAngleDeg), at most `gap` cells
// apart along their normal, and overlapping over at least kSideOverlap of the shorter side.
// `from`, `to`: the seam, both sides' extent together, on the line midway between them; `lo`,
// `hi`: where they overlap, as distances from `from` towards `to`. a < b (unit ids).
struct SideMatch {
  int a = 0;
  int b = 0;
  Point2 from, to;
  double lo = 0.0, hi = 0.0;
};

constexpr double kSideAngleDeg = 2.0;
constexpr double kSideOverlap = 0.5;

// All such pairs of `units` (the longest overlap of each pair), ordered by (a, b); units with a
// degenerate quad never match.
std::vector<SideMatch> matching_sides(const std::vector<UnitResult>& units, double gap);

constexpr double kSeamGap = 2.0;     // cells between the facing sides of two units that continue each other
constexpr double kSeamBeside = 4.0;  // cells: the lines either side of the seam it is compared with
constexpr double kFreeBeside = 0.5;  // of the cells beside the seam free
constexpr double kOpenSeam = 0.9;    // of the free cells beside the seam free on it
constexpr double kSharedSeam = 0.9;  // of the free cells on the seam where both sides are

// The pairs of `units` that continue each other on `grid`: matching_sides within kSeamGap whose
// seam is the whole passage between them. Sampled one cell apart along the seam and along the
// two lines kSeamBeside cells either side of it:
// - the more open line beside the seam is at least kFreeBeside free (the units hold a passage);
// - the seam has at least kOpenSeam as many free cells as that line. A wall with a door narrows
//   the seam (a 0.9 m door in a 1.1 m corridor leaves 82 % of it); furniture or a jagged wall
//   face runs on beside it;
// - at least kSharedSeam of the seam's free cells lie where both sides are: the passage runs
//   from one unit into the other, not past the end of one of them. The units' own ends may lie
//   anywhere in the walls.
// Ordered by (a, b).
std::vector<std::pair<int, int>> continued_units(const ClassGrid& grid, const std::vector<UnitResult>& units);

}  // namespace ksmc::stdlib::indoor::io
