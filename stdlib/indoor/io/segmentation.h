// segmentation.png: a room segmentation of the input map from the world's units, in the form
// room-segmentation benchmarks read (16-bit, 0 = no room, otherwise the unit id; ids are > 0).
//
// Fill rule, per cell of the map:
//   * walls (occupied) and unknown cells stay 0, except free-standing furniture (last rule);
//   * a free cell whose centre lies inside one or more units gets the unit it lies deepest
//     inside (largest distance from the cell centre to the rectangle's boundary; ties: the
//     unit with the nearer centre, then the smaller id). Where two units overlap, the boundary between them is then the mid line of
//     the overlap, a straight line, and a thin unit lying across a wall or along a big room's
//     edge (whose cells are never deep inside it) cannot cut a strip out of the room;
//   * a space no unit reaches gets an id of its own (above every unit id): the free cells over
//     0.6 m from every wall or unknown cell, in 4-connected components (passages up to 1.2 m
//     wide, doors, cut them apart), of which a component with no cell inside a unit and at
//     least 0.5 m^2 large seeds a new segment. Without it the fill below gives a whole room no
//     unit covers, through its door, to a unit of the next room;
//   * every other free cell gets the unit or space nearest to it through free space: a multi-source
//     breadth-first search over 4-connected free cells from the cells labelled so far (ties:
//     the unit reached first in row-major seed order, so the result is deterministic). The
//     search moves only between edge-adjacent free cells, so it never leaks through the
//     diagonal gap between two wall pixels that touch at a corner;
//   * free space the search reached only through a doorway is a space of its own: a
//     component of searched cells (one label, at least 1 m^2) whose contact with the cells
//     its unit or space explains is at most 1.2 m gets a new id, touching ones the same id
//     (a corridor no unit covers, too narrow for a core; doorway_spaces.h);
//   * a free component no unit or space reaches (a room narrower than 1.2 m or too small for
//     a core, behind a wall) is a space of its own when it is at least 0.25 m^2; smaller ones
//     (scan speckle) stay 0;
//   * two segments that meet over more than 2 m of free cells (4-neighbour pairs) are one
//     space (the `@one_space` rule's 2 m): furniture cutting a room's core in pieces, or a unit
//     covering part of a room open to it. Two units are joined only when, besides, more than
//     0.5 m of that contact lies over 0.6 m from every wall, the wall runs (at most 0.4 m
//     thick) between them are at most a quarter of the contact, and the smaller is under
//     20 m^2: a sliver or a corridor piece, not a room beside a wide opening. Widest contact
//     first. A corridor continues: two corridor-shaped units (under 2.6 m across, or under
//     4 m and 3 times as long) are joined whatever their size when their free contact exceeds
//     1.2 m and 3/4 of the narrower one's width, with the same limit on the walls between
//     them: a ring or an L of corridor pieces meets over the corridor's width. A joined
//     segment keeps the id of one of its units: of the unit types in it, the one whose units
//     hold most of its cells; of those units, the one with the largest segment of its own;
//   * a segment that a straight wall line with a gap (at most 3 m) crosses is two spaces (wall
//     lines along the rows and columns of the building's frame: dominant_wall_angle): an
//     office open to its corridor over 2-3 m between wall stubs gets its own id (the stubs'
//     blobs span at least 1 m: chairs in a row round a table are no wall line); thin
//     partitions at any angle cut at the gaps between their pieces and at the doorway (up to
//     1.4 m) beyond a free end (split_at_wall_gaps, wall_gap_cuts.h, thin_walls.h). A cut
//     across a corridor-shaped unit from wall to wall, inside it and walled on both sides, is
//     none: a corridor continues where the partitions of the rooms beside it line up across it
//     (a door frame's stubs narrow it, and that cut stays). A piece
//     cut off a joined segment gets back the id of the unit its cells mostly were, when no
//     other segment has it, else a new id;
//   * an occupied 8-connected blob of at most 4 m^2, off the map's edge, whose 4-neighbours are
//     all free cells of one segment is furniture standing in that room: it gets the segment.
#pragma once

#include <filesystem>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// Unit id per cell, grid.rows x grid.cols (grid holds Cell values).
cv::Mat1w render_segmentation(const ClassGrid& grid, const WorldResult& w);

void write_segmentation_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
