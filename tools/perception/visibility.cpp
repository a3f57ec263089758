#include "tools/perception/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::perception {

namespace {

// Whether the seen surface points' spans along box b's axes (lo, hi: box frame) cover its extents.
bool extents_shown(const tools::tabletop_sim::Box& b, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                   double tolerance) {
  if (!(lo.array() <= hi.array()).all()) return false;  // no point seen
  const Eigen::Matrix3d r = b.pose.rotation();
  const bool on_table = tools::tabletop_sim::lowest_z(b) <= tolerance;
  for (int k = 0; k < 3; ++k) {
    if (hi(k) - lo(k) >= b.size(k) - tolerance) continue;
    // Standing on the table along axis k: the table is its bottom, its top must be seen.
    const double up = r(2, k);
    const bool vertical = std::abs(up) >= std::cos(2.0 * 3.14159265358979323846 / 180.0);
    const double top = up > 0.0 ? hi(k) : -lo(k);
    if (on_table && vertical && top >= 0.5 * b.size(k) - tolerance) continue;
    return false;
  }
  return true;
}

}  // namespace

std::vector<BoxView> box_views(const tools::tabletop_sim::Camera& camera,
                               const tools::tabletop_sim::Pose& table_from_camera,
                               std::span<const tools::tabletop_sim::Box> boxes, int stride, double tolerance) {
  const std::size_t n = boxes.size();
  std::vector<long> alone(n, 0), seen(n, 0);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> lo(n, Eigen::Vector3d::Constant(inf)), hi(n, Eigen::Vector3d::Constant(-inf));
  std::vector<Eigen::Matrix3d> to_box(n);
  for (std::size_t i = 0; i < n; ++i) to_box[i] = boxes[i].pose.rotation().transpose();
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
      double best = inf;
      std::size_t nearest = n;
      for (std::size_t i = 0; i < n; ++i) {
        const double s = tools::tabletop_sim::ray_box(eye, dir, boxes[i]);
        if (s <= 0.0) continue;
        ++alone[i];
        if (s < best) best = s, nearest = i;
      }
      if (!in_image || nearest == n) continue;
      ++seen[nearest];
      const Eigen::Vector3d local = to_box[nearest] * (eye + best * dir - boxes[nearest].pose.t);
      lo[nearest] = lo[nearest].cwiseMin(local);
      hi[nearest] = hi[nearest].cwiseMax(local);
    }
  std::vector<BoxView> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (alone[i] > 0) out[i].visible = static_cast<double>(seen[i]) / static_cast<double>(alone[i]);
    out[i].extents_shown = extents_shown(boxes[i], lo[i], hi[i], tolerance);
  }
  return out;
}

}  // namespace ksmc::tools::perception
