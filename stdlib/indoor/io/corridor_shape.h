// Which units are corridor-shaped, for the segmentation's post-steps (segmentation.cpp joins
// corridor pieces, wall_gap_cuts.cpp keeps a corridor whole where partitions line up across it).
// The thresholds are those of the domain's `Narrow` and `CoLi` evidence (domains/indoor.ksm,
// geom.corridor_like: Table 3.6's corridor shape).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "stdlib/indoor/io/quad.h"

namespace ksmc::stdlib::indoor::io {

constexpr double kNarrowUnit = 2.6;  // m across: a corridor (`Narrow` in domains/indoor.ksm)
constexpr double kLongUnit = 4.0;    // m across, at least kLongRatio times as long: a corridor
constexpr double kLongRatio = 3.0;

// The width of a corridor-shaped unit in cells: its shorter side when it is under kNarrowUnit,
// or under kLongUnit and kLongRatio times as long; infinity otherwise (and for a degenerate quad).
// `res`: metres per cell.
inline double corridor_width(const Quad& q, double res) {
  constexpr double kNot = std::numeric_limits<double>::infinity();
  if (!finite_quad(q)) return kNot;
  const double a = std::hypot(q[1].x - q[0].x, q[1].y - q[0].y), b = std::hypot(q[2].x - q[1].x, q[2].y - q[1].y);
  if (!(a > 0.0) || !(b > 0.0)) return kNot;
  const double w = std::min(a, b) * res, l = std::max(a, b) * res;
  return w < kNarrowUnit || (w < kLongUnit && l >= kLongRatio * w) ? std::min(a, b) : kNot;
}

}  // namespace ksmc::stdlib::indoor::io
