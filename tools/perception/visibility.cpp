#include "tools/perception/visibility.h"

#include <algorithm>
#include <limits>

namespace ksmc::tools::perception {

std::vector<double> visible_fractions(const tools::tabletop_sim::Camera& camera,
                                      const tools::tabletop_sim::Pose& table_from_camera,
                                      std::span<const tools::tabletop_sim::Box> boxes, int stride) {
  const std::size_t n = boxes.size();
  std::vector<long> alone(n, 0), seen(n, 0);
  const Eigen::Matrix3d r = table_from_camera.rotation();
  const Eigen::Vector3d eye = table_from_camera.t;
  const int step = std::max(1, stride);
  for (int v = 0; v < camera.height; v += step)
    for (int u = 0; u < camera.width; u += step) {
      const Eigen::Vector3d dir = r * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      double best = std::numeric_limits<double>::infinity();
      std::size_t nearest = n;
      for (std::size_t i = 0; i < n; ++i) {
        const double s = tools::tabletop_sim::ray_box(eye, dir, boxes[i]);
        if (s <= 0.0) continue;
        ++alone[i];
        if (s < best) best = s, nearest = i;
      }
      if (nearest < n) ++seen[nearest];
    }
  std::vector<double> out(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (alone[i] > 0) out[i] = static_cast<double>(seen[i]) / static_cast<double>(alone[i]);
  return out;
}

}  // namespace ksmc::tools::perception
