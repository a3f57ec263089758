#include "stdlib/tabletop/tilt_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop {

TiltNoise tilt_noise(const Scene& scene, double stable_tol) {
  std::vector<double> tilts;
  for (const auto& o : scene.objects) {
    const double t = tilt_angle(o.obb());
    if (t <= stable_tol) tilts.push_back(t);
  }
  TiltNoise n;
  n.tilts = tilts.size();
  if (tilts.empty()) return n;
  // The median (the mean of the middle two for an even count).
  const auto mid = tilts.begin() + static_cast<std::ptrdiff_t>(tilts.size() / 2);
  std::nth_element(tilts.begin(), mid, tilts.end());
  double median = *mid;
  if (tilts.size() % 2 == 0) median = 0.5 * (median + *std::max_element(tilts.begin(), mid));
  n.sigma = median / std::sqrt(2.0 * std::log(2.0));
  return n;
}

}  // namespace ksmc::stdlib::tabletop
