// The thin walls of a map as straight lines, for the segmentation's wall-line cuts
// (wall_gap_cuts.h). A thin wall is a run of occupied cells at most kMaxWallThickness across,
// along a row or a column, with free cells at both of its ends: a partition between two spaces,
// at any angle and one cell thin or thicker. Outer walls (unknown space or the map edge beyond
// them) and furniture blocks wider than that are not thin. Hough segments of those cells that
// lie on one line (within 1.5 degrees and 2 cells across) are one line: a partition with its
// door openings.
#pragma once

#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor::io {

inline constexpr double kMaxWallThickness = 0.4;  // m across a wall: a wall, not a block

// 255 where a cell is Occupied and, along its row or its column, the occupied run through it is
// at most `max_cells` long with Free cells at both ends; 0 elsewhere.
cv::Mat1b thin_wall_mask(const ClassGrid& map, int max_cells);

// One thin wall line: points origin + t * dir (cells, |dir| = 1); the wall covers the sorted,
// disjoint intervals [lo, hi] of t.
struct WallLine {
  Point2 origin, dir;
  std::vector<std::pair<double, double>> covered;
  Point2 at(double t) const { return {origin.x + t * dir.x, origin.y + t * dir.y}; }
};

// The thin wall lines of `map` (`resolution` m per cell): Hough segments at least 1 m long of
// thin_wall_mask, grouped by line. Deterministic; empty for an empty map.
std::vector<WallLine> thin_wall_lines(const ClassGrid& map, double resolution);

}  // namespace ksmc::stdlib::indoor::io
