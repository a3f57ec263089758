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
  // The image plane is read one image width and height past each border for `alone`: a box
  // the border cuts is partly unseen (before stop 44 only the pixels inside the image counted,
  // and a book whose top the border cut by a fifth read as 100 % visible).
  for (int v = -camera.height; v < 2 * camera.height; v += step)
    for (int u = -camera.width; u < 2 * camera.width; u += step) {
      const Eigen::Vector3d dir = r * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      const bool in_image = u >= 0 && u < camera.width && v >= 0 && v < camera.height;
      double best = std::numeric_limits<double>::infinity();
      std::size_t nearest = n;
      for (std::size_t i = 0; i < n; ++i) {
        const double s = tools::tabletop_sim::ray_box(eye, dir, boxes[i]);
        if (s <= 0.0) continue;
        ++alone[i];
        if (s < best) best = s, nearest = i;
      }
      if (in_image && nearest < n) ++seen[nearest];
    }
  std::vector<double> out(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (alone[i] > 0) out[i] = static_cast<double>(seen[i]) / static_cast<double>(alone[i]);
  return out;
}

}  // namespace ksmc::tools::perception
