// Bias of proposals toward the map's dominant orientation (from the detect module) without
// forbidding others: a candidate at angular distance d (modulo 90 degrees) from the dominant
// orientation has its weight multiplied by floor + (1 - floor) * exp(-d^2 / (2 sigma^2)).
#pragma once

#include <cmath>

#include "stdlib/indoor/geometry.h"

namespace ksmc::stdlib::indoor {

struct OrientationBias {
  bool enabled = false;
  double dominant = 0.0;                 // radians
  double sigma = 5.0 * kPi / 180.0;      // radians
  double floor = 0.2;                    // in (0, 1]: weight kept by a perpendicular-to-nothing angle
  double factor(double theta) const {
    if (!enabled) return 1.0;
    const double d = angle_off_quarter(theta - dominant);
    return floor + (1.0 - floor) * std::exp(-d * d / (2.0 * sigma * sigma));
  }
};

}  // namespace ksmc::stdlib::indoor
