// Candidate types produced by the indoor bottom-up detectors (seed §3.5.2) and consumed
// by the ADD, SPLIT and ALLOCATE kernels. Geometry is in continuous cell coordinates
// (x = column, y = row, image convention); the centre of cell (c, r) is the point (c, r).
#pragma once

#include <cmath>

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor::detect {

// A line segment in cell coordinates.
struct Segment {
  Point2 a, b;
  double length() const { return std::hypot(b.x - a.x, b.y - a.y); }
};

// A proposed unit (ADD): rectangle whose sides lie on wall centre lines, weight eq. 3.10.
struct UnitCandidate {
  OrientedRect rect;
  double weight = 0.0;
};

// A proposed cut of a unit (SPLIT): from one wall of the unit to the opposite one;
// weight = supporting Hough length (eq. 3.18).
struct SplitLine {
  Point2 a, b;
  double weight = 0.0;
};

// A proposed door (ALLOCATE): segment on the shared wall of two units, weight eq. 3.23.
// unit_a / unit_b index the `units` argument of detect_doors (-1 when not known).
struct DoorCandidate {
  Point2 a, b;
  double weight = 0.0;
  int unit_a = -1;
  int unit_b = -1;
};

// Whether a detector validates its class grid first (an O(map) scan: every value a Cell).
// Trusted: the caller validated this grid already and calls the detector many times on it
// (the kit's per-pair door refresh, split lines per unit), so the scan would dominate.
enum class GridCheck { Full, Trusted };

}  // namespace ksmc::stdlib::indoor::detect
