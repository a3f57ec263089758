// Small geometry of a unit's corner quadrilateral (convex, corners in order, either winding),
// shared by the writers that fill, extrude or route through units.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor::io {

using Quad = std::array<Point2, 4>;

inline bool finite_quad(const Quad& q) {
  return std::all_of(q.begin(), q.end(), [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

// Twice the signed area in image coordinates (y down): > 0 when the inside is left of each edge.
inline double signed_area2(const Quad& q) {
  double a = 0.0;
  for (std::size_t k = 0; k < 4; ++k) a += q[k].x * q[(k + 1) % 4].y - q[(k + 1) % 4].x * q[k].y;
  return a;
}

// Distance from p to the boundary of q, positive inside, negative outside (the smallest signed
// edge distance); -infinity for a degenerate quad (zero area or a zero-length edge).
inline double depth_inside(const Quad& q, Point2 p) {
  const double area2 = signed_area2(q);
  if (area2 == 0.0 || !std::isfinite(area2)) return -std::numeric_limits<double>::infinity();
  const double orientation = area2 > 0.0 ? 1.0 : -1.0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < 4; ++i) {
    const Point2 a = q[i], b = q[(i + 1) % 4];
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double len = std::hypot(ex, ey);
    if (!(len > 0.0)) return -std::numeric_limits<double>::infinity();
    d = std::min(d, orientation * (ex * (p.y - a.y) - ey * (p.x - a.x)) / len);
  }
  return d;
}

}  // namespace ksmc::stdlib::indoor::io
