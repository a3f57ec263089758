#include "stdlib/tabletop/extract_hides.h"

#include "stdlib/tabletop/line_of_sight.h"

namespace ksmc::stdlib::tabletop {

namespace {

constexpr int kGrid = 6;  // samples per face side: 36 per face, at most 3 faces face a camera

}  // namespace

double covered_share(const Obb& front, const Obb& seen, const Eigen::Vector3d& camera, double margin) {
  const Eigen::Vector3d core = front.half.array() - margin;
  if ((core.array() <= 0.0).any()) return 0.0;
  if (!sight_may_cross(camera, seen.center, seen.half.norm(), front.center, core.norm())) return 0.0;
  Obb shrunk = front;
  shrunk.half = core;
  const Eigen::Vector3d eye = in_box_axes(shrunk, camera - shrunk.center);
  double total = 0.0, covered = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double sign : {-1.0, 1.0}) {
      const Eigen::Vector3d normal = sign * seen.axes.col(axis);
      const Eigen::Vector3d centre = seen.center + seen.half[axis] * normal;
      const Eigen::Vector3d to_camera = camera - centre;
      const double cosine = normal.dot(to_camera) / to_camera.norm();
      if (!(cosine > 0.0)) continue;
      const double weight = cosine * seen.half[u] * seen.half[v];  // per face; samples share it equally
      int behind = 0;
      for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
          const double a = (2.0 * i + 1.0) / kGrid - 1.0, b = (2.0 * j + 1.0) / kGrid - 1.0;  // cell centres in (-1, 1)
          const Eigen::Vector3d p = centre + a * seen.half[u] * seen.axes.col(u) + b * seen.half[v] * seen.axes.col(v);
          behind += segment_crosses(shrunk, eye, camera, p, margin) ? 1 : 0;
        }
      }
      total += weight;
      covered += weight * behind / (kGrid * kGrid);
    }
  }
  return total > 0.0 ? covered / total : 0.0;
}

bool extract_hides(const Obb& front, const Obb& seen, int keypoints, const Eigen::Vector3d& camera, double margin,
                   double min_expected) {
  if (keypoints <= 0) return false;
  const double share = covered_share(front, seen, camera, margin);
  if (share <= 0.0) return false;
  if (share >= 1.0) return true;  // all of it covered: any keypoint it has would be behind the front box
  return keypoints * share / (1.0 - share) >= min_expected;
}

}  // namespace ksmc::stdlib::tabletop
