// How well walls and doors match the classified map.
//  wall weight  (eq. 3.11-3.14): w = n(w)/l(w), n counts the wall samples that fall on
//               occupied cells. The seed's 3.14 writes "C_M = 0" in the dissertation's
//               numbering where 0 meant occupied (Table 3.1); here that is Cell::Occupied.
//  unit weight  (eq. 3.10): the lowest of the four wall weights.
//  door weight  (eq. 3.23-3.25): w = n'(g)/l(g), n' counts samples on free cells.
// A segment of length l is sampled at ceil(l) + 1 equally spaced points (cell centres by
// rounding), so l(w) is the number of samples and weights lie in [0, 1]; cells outside the
// map never match.
#pragma once

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

struct WallScoreParams {
  // A wall sample matches when an occupied cell lies within this many cells of it,
  // perpendicular to the wall: absorbs the placement error of thick or drifting SLAM walls
  // (2 cells = 0.1 m, the same as WbuParams::wall_tolerance).
  int tolerance = 2;
};

double wall_weight(const ClassGrid& grid, Point2 a, Point2 b, const WallScoreParams& params = {});
double unit_weight(const ClassGrid& grid, const OrientedRect& rect, const WallScoreParams& params = {});

struct DoorScoreParams {
  // A door sample is free when its cell is Free and no cell within this many cells across
  // the wall (both sides) is Occupied: a door must be open through the whole wall. 0 gives
  // eq. 3.25 literally.
  int half_width = 0;
};

double door_weight(const ClassGrid& grid, Point2 a, Point2 b, const DoorScoreParams& params = {});

}  // namespace ksmc::stdlib::indoor::detect
