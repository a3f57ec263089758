#include "stdlib/tabletop/extract_stable.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::tabletop {

double tilt_angle(const Obb& box) {
  double best = 0.0;
  for (int i = 0; i < 3; ++i) best = std::max(best, std::abs(box.axes(2, i)));
  return std::acos(std::min(1.0, best));
}

bool extract_stable(const Obb& box, const EvidenceParams& params) {
  return tilt_angle(box) <= params.stable_tol_rad;
}

}  // namespace ksmc::stdlib::tabletop
