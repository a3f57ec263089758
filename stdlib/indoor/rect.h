// An oriented rectangle in continuous cell coordinates (x = column, y = row, image convention).
// Units of the indoor world are such rectangles; detectors propose them.
#pragma once

#include <array>
#include <cmath>

namespace ksmc::stdlib::indoor {

struct Point2 {
  double x = 0.0;  // column, cells
  double y = 0.0;  // row, cells
};

struct OrientedRect {
  double cx = 0.0, cy = 0.0;  // centre, cells
  double w = 0.0, h = 0.0;    // full extents along the rectangle's own axes, cells
  double theta = 0.0;         // rotation of the w-axis from the x (column) axis, radians

  // Corners in order around the rectangle: (-w,-h), (+w,-h), (+w,+h), (-w,+h) halves, rotated.
  std::array<Point2, 4> corners() const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double hw = 0.5 * w, hh = 0.5 * h;
    const double lx[4] = {-hw, hw, hw, -hw};
    const double ly[4] = {-hh, -hh, hh, hh};
    std::array<Point2, 4> out{};
    for (int i = 0; i < 4; ++i) out[i] = {cx + c * lx[i] - s * ly[i], cy + s * lx[i] + c * ly[i]};
    return out;
  }
  double area() const { return w * h; }
};

}  // namespace ksmc::stdlib::indoor
