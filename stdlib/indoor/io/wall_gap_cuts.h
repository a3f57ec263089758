// A room segmentation's post-step (segmentation.png): a segment that a straight wall line with
// a gap crosses is two spaces. Defect it addresses (docs/indoor_knowledge_segmentation.md, "Open office
// fronts"): a row of offices whose door side is open to the corridor over 2-3 m (wider than a
// door, so the chain's `@one_space` rule calls office and corridor one space) ends up in one
// unit; a person, and the Bormann et al. ground truth, draw the room boundary along the line
// of the wall stubs on either side of each opening.
//
// Rule, per row and per column of the map (of the building's frame: `wall_angle` below): a run
// of free, labelled cells at most kMaxGap long whose two ends are wall cells where a wall
// continues straight on along the run's line (at least kWallRun of occupied cells beyond each
// end, and that wall at most kMaxWallThickness thick across the line) is a gap in a wall line,
// a cut, when the occupied blob (8-connected) at each end spans at least kMinWallPiece (1 m):
// part of a wall, not a chair. A wall crossed across its thickness, a thick block, furniture
// that does not line up on both ends, or a row of chairs round a table gives no cut. The cells
// of a segment minus its cut cells fall into 4-connected pieces; when two or more pieces are at
// least kMinPiece large, the largest keeps the segment's id, each other one gets a new id (above
// every id in use; or its unit's id back, below), and the cut cells and small pieces go to the
// nearest large piece of their segment through the segment's cells. A segment with fewer than
// two large pieces is unchanged, so a cut that does not separate a space (a gap between two
// tables) changes nothing.
//
// Thin walls at any angle (thin_walls.h: partitions at most 0.4 m thick with free space on both
// sides, found as Hough lines, so one-cell walls drawn slightly off the grid axes count) give
// cuts too (docs/indoor_knowledge_segmentation.md, "Partitions with wide openings"):
//   * the gap between two pieces of one wall line, up to kMaxGap, when it holds only free,
//     labelled cells (a corridor with its own walls between two collinear partitions is no gap);
//   * beyond a wall line's free end, the free, labelled run along the line up to kMaxEndGap
//     (1.4 m: a door of up to 1.2 m and the slack of a Hough end; less than a corridor is wide)
//     to the first occupied cell: the doorway between a
//     partition's end and the wall it points at. A line that ends in a junction (a wall across
//     it within 2 cells of its end) has no free end there.
#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// `before_join`, when not null: the labels before merge_open_spaces joined segments. A piece
// cut off a segment takes back the id its cells mostly had there, when that id is in use
// nowhere else (a unit the join had absorbed: the piece keeps its unit's id, and so its type);
// otherwise a new id.
//
// `wall_angle` (radians, dominant_wall_angle): the direction of the building's walls modulo 90
// degrees. The row and column scans run in the building's frame: along the map's rows and
// columns when the walls are within 1 degree of them, else on the map turned by that angle, so
// that on a map whose building is not aligned with the image a thick wall crossed obliquely
// gives no cut. On the turned map a wall's faces are jagged by a cell, so there the wall beyond
// a gap's end must be thin across at its last two cells, not at its last one alone: a wall
// crossing the row, about as thick as kWallRun, is then no wall lying along the row.
//
// `units`, when not null: the world's units. A cut that crosses a corridor-shaped unit
// (corridor_shape.h) from side to side (over its width less 0.15 m at each side, and at least
// 3/4 of it; a door frame's stubs narrow it more), at most 0.5 m along it and at least the
// unit's width from both of its ends, with the corridor walled on both sides of it, is no cut: a corridor continues where the partitions of the rooms on both sides line up
// across it (Freiburg79_scan: its corridor was cut at the first such pair).
void split_at_wall_gaps(const ClassGrid& grid, double resolution, cv::Mat1w& label,
                        const cv::Mat1w* before_join = nullptr, double wall_angle = 0.0,
                        const std::vector<UnitResult>* units = nullptr);

// The direction of the units' edges modulo 90 degrees, in radians in [-pi/4, pi/4): of the
// units' directions, the one with the most unit area within 3 degrees of it, refined to the
// area-weighted mean there. 0 for a world without units, and when that direction holds under
// 85 % of the units' area (office_e's pentagon, 65-81 % on seeds 1-3: no one frame), so that rows and
// columns are scanned.
double dominant_wall_angle(const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
