#include "stdlib/tabletop/extract_blocks.h"

#include <algorithm>

#include "stdlib/tabletop/line_of_sight.h"

namespace ksmc::stdlib::tabletop {

int keypoints_behind(const Obb& front, const Pose& seen_pose, std::span<const Eigen::Vector3d> model_points,
                     const Eigen::Vector3d& camera, double margin) {
  const Eigen::Vector3d core = front.half.array() - margin;
  if ((core.array() <= 0.0).any()) return 0;
  double seen_radius = 0.0;
  for (const Eigen::Vector3d& m : model_points) seen_radius = std::max(seen_radius, m.norm());
  if (!sight_may_cross(camera, seen_pose.t, seen_radius, front.center, core.norm())) return 0;
  Obb shrunk = front;
  shrunk.half = core;
  const Eigen::Vector3d eye = in_box_axes(shrunk, camera - shrunk.center);
  int hidden = 0;
  for (const Eigen::Vector3d& m : model_points)
    hidden += segment_crosses(shrunk, eye, camera, seen_pose.q * m + seen_pose.t, margin) ? 1 : 0;
  return hidden;
}

bool extract_blocks(const Obb& front, const Pose& seen_pose, std::span<const Eigen::Vector3d> model_points,
                    const Eigen::Vector3d& camera, double margin, int min_keypoints, double min_fraction) {
  if (model_points.empty()) return false;
  const int hidden = keypoints_behind(front, seen_pose, model_points, camera, margin);
  return hidden >= std::max(min_keypoints, 1) &&
         static_cast<double>(hidden) >= min_fraction * static_cast<double>(model_points.size());
}

}  // namespace ksmc::stdlib::tabletop
