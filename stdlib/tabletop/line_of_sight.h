// Lines of sight through boxes: whether the segment from a sensor to an observed point passes
// through a box before the point. A seen point has nothing solid on that segment, so the cloud
// likelihood's free-space term (cloud_likelihood.h: rays a box blocks) and the keypoint
// evidence `obb.blocks` (extract_blocks.h) and `obb.hides` (extract_hides.h) count such
// crossings. Header-only: the likelihood calls it once per ray and box, and GCC inlines it there.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// A vector in the box's axes. Three dot products, not axes.transpose() * v: GCC inlines these
// at -O2 and left the general product out of line (2x the time per point in
// bench_tabletop_perception's likelihood).
inline Eigen::Vector3d in_box_axes(const Obb& box, const Eigen::Vector3d& v) {
  return {box.axes.col(0).dot(v), box.axes.col(1).dot(v), box.axes.col(2).dot(v)};
}

// Narrows [enter, leave] (parameters of the line o + t d, box frame) to where the line is
// inside the box; false when nothing is left (the slab test).
inline bool slab_span(const Obb& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double& enter, double& leave) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (std::abs(o[k]) > box.half[k]) return false;
      continue;
    }
    double s0 = (-box.half[k] - o[k]) / d[k], s1 = (box.half[k] - o[k]) / d[k];
    if (s0 > s1) std::swap(s0, s1);
    enter = std::max(enter, s0);
    leave = std::min(leave, s1);
    if (enter > leave) return false;
  }
  return true;
}

// Whether the segment sensor -> p, stopping `margin` before p, passes through the box; `o` is
// the sensor in the box frame (in_box_axes(box, sensor - box.center)).
inline bool segment_crosses(const Obb& box, const Eigen::Vector3d& o, const Eigen::Vector3d& sensor,
                            const Eigen::Vector3d& p, double margin) {
  const Eigen::Vector3d seg = p - sensor;
  const double len = seg.norm();
  if (len <= margin) return false;
  double enter = 0.0, leave = 1.0 - margin / len;  // segment parameter where the check stops
  return slab_span(box, o, in_box_axes(box, seg), enter, leave);
}

// False only when no line of sight from `camera` to a point within `seen_radius` of `seen_centre`
// can pass within `front_radius` of `front_centre`: the front sphere lies beyond all of them, or
// outside the cone of those lines. A cheap test that skips the pairs nowhere near each other.
inline bool sight_may_cross(const Eigen::Vector3d& camera, const Eigen::Vector3d& seen_centre, double seen_radius,
                            const Eigen::Vector3d& front_centre, double front_radius) {
  const Eigen::Vector3d to_seen = seen_centre - camera, to_front = front_centre - camera;
  const double d_seen = to_seen.norm(), d_front = to_front.norm();
  if (d_seen <= seen_radius || d_front <= front_radius) return true;  // the camera inside a sphere
  if (d_front - front_radius > d_seen + seen_radius) return false;     // behind every point
  const double cosine = std::clamp(to_seen.dot(to_front) / (d_seen * d_front), -1.0, 1.0);
  return std::acos(cosine) <= std::asin(seen_radius / d_seen) + std::asin(front_radius / d_front);
}

}  // namespace ksmc::stdlib::tabletop
