#include "stdlib/tabletop/perception/hidden_reach.h"

#include <algorithm>
#include <cmath>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/perception/footprint.h"
#include "stdlib/tabletop/perception/ray_meeting.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

// The footprint of an upright box.
Rect2 footprint(const UprightBox& box) {
  Rect2 r;
  r.center = box.pose.t.head<2>();
  r.u = (box.pose.q * Eigen::Vector3d::UnitX()).head<2>().normalized();
  r.half = 0.5 * box.size.head<2>();
  return r;
}

// Whether a box of `boxes` other than `lower` and `upper` holds one of 5 x 5 x 5 points
// spanning `space`.
bool held_by_another(const Obb& space, const std::vector<UprightBox>& boxes, std::size_t lower, std::size_t upper) {
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (k == lower || k == upper) continue;
    const Obb other = Obb::from_pose(boxes[k].pose, boxes[k].size);
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b)
        for (int c = 0; c < 5; ++c) {
          const Eigen::Vector3d u((a / 2.0 - 1.0), (b / 2.0 - 1.0), (c / 2.0 - 1.0));
          if (other.contains(space.center + space.axes * u.cwiseProduct(space.half))) return true;
        }
  }
  return false;
}

}  // namespace

int grow_hidden_reach(std::vector<UprightBox>& boxes, const RayIndex& rays, const HiddenReachOptions& options) {
  if (!options.enabled) return 0;
  // Whether `upper` rests on `lower`: its bottom near the lower box's top, their footprints
  // overlapping or nearly (a strip beside the box on it, within half the gap).
  const auto rests_on = [&options](const UprightBox& upper, const UprightBox& lower) {
    const double top = bottom_height(lower) + lower.size.z();
    return std::abs(bottom_height(upper) - top) <= options.rest_gap &&
           rects_overlap(footprint(upper), footprint(lower), 0.5 * options.rest_gap);
  };
  int grown = 0;
  for (std::size_t u = 0; u < boxes.size(); ++u) {
    if (!is_upright(boxes[u])) continue;
    // One box under it: on two or more (a book across two boxes), its centre need be over none.
    std::size_t l = boxes.size(), count = 0;
    for (std::size_t k = 0; k < boxes.size(); ++k)
      if (k != u && rests_on(boxes[u], boxes[k])) l = k, ++count;
    if (count != 1 || !is_upright(boxes[l])) continue;
    UprightBox& lower = boxes[l];
    const double bottom = bottom_height(lower), top = bottom + lower.size.z();
    const Eigen::Matrix3d r = lower.pose.q.toRotationMatrix();
    const Eigen::Vector3d centre = r.transpose() * (boxes[u].pose.t - lower.pose.t);  // in the lower box's axes
    for (int a = 0; a < 2; ++a) {
      const double half = 0.5 * lower.size(a);
      const double growth = std::abs(centre(a)) + options.margin - half;
      if (growth <= 0.0 || growth > options.max_growth) continue;
      const double side = centre(a) > 0.0 ? 1.0 : -1.0;
      const double probe = std::max(growth, options.min_probe);
      Obb space;  // the space the side grows into, over the lower box's height, inset
      space.axes = r;
      Eigen::Vector3d local = Eigen::Vector3d::Zero();
      local(a) = side * (half + 0.5 * probe);
      local.z() = 0.5 * (bottom + top) - lower.pose.t.z();
      space.center = lower.pose.t + r * local;
      space.half(a) = 0.5 * probe - options.inset;
      space.half(1 - a) = 0.5 * lower.size(1 - a) - options.inset;
      space.half.z() = 0.5 * (top - bottom) - options.inset;
      if (space.half.minCoeff() <= 0.0 || held_by_another(space, boxes, l, u)) continue;
      // The lower box's own points left out: its front hides its back trivially. A ray ending on
      // the box on it hides the space; one ending behind the space saw it empty.
      const SpaceUnder s = rays_meeting(space, {Obb::from_pose(lower.pose, lower.size)}, rays, options.ray_margin);
      const std::size_t all = s.before + s.inside + s.through;
      if (s.before < options.min_rays || static_cast<double>(s.before) < options.hidden_share * static_cast<double>(all))
        continue;
      lower.size(a) += growth;
      Eigen::Vector3d shift = Eigen::Vector3d::Zero();
      shift(a) = side * 0.5 * growth;
      lower.pose.t += r * shift;
      ++grown;
    }
  }
  return grown;
}

}  // namespace ksmc::stdlib::tabletop::perception
