#include "stdlib/tabletop/perception/tilted_foot.h"

#include <cmath>
#include <limits>
#include <optional>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/obb_sat.h"
#include "stdlib/tabletop/perception/ray_meeting.h"

namespace ksmc::stdlib::tabletop::perception {

int grow_tilted_feet(std::vector<UprightBox>& boxes, const RayIndex& rays, const TiltedFootOptions& o) {
  if (!o.enabled) return 0;
  int grown = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (is_upright(boxes[i])) continue;
    const Obb fit = Obb::from_pose(boxes[i].pose, boxes[i].size);
    const double low = fit.min_z();
    if (low <= o.gap) continue;
    std::optional<UprightBox> best;
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d axis = fit.axes.col(k);
      const double slope = std::abs(axis.z());
      if (slope < o.min_slope) continue;
      const double growth = low / slope;
      if (growth > o.max_growth || growth >= least) continue;
      const double down = axis.z() > 0.0 ? -1.0 : 1.0;  // the side of axis k that is lower
      Obb added;  // what the box grows into
      added.axes = fit.axes;
      added.half = fit.half;
      added.half(k) = 0.5 * growth;
      added.center = fit.center + down * (fit.half(k) + 0.5 * growth) * axis;
      bool cuts = false;  // the box may already cut into the one it leans on (lean_seat.h comes later)
      for (std::size_t j = 0; j < boxes.size() && !cuts; ++j) {
        if (j == i) continue;
        const SatResult r = obb_sat(added, Obb::from_pose(boxes[j].pose, boxes[j].size));
        cuts = r.overlapping && r.depth > o.clear;
      }
      if (cuts) continue;
      Obb part = added;  // inset for the rays
      part.half -= Eigen::Vector3d::Constant(o.inset);
      if (part.half.minCoeff() <= 0.0) continue;
      const SpaceUnder seen = rays_meeting(part, {fit}, rays, o.margin);
      const double all = static_cast<double>(seen.before + seen.inside + seen.through);
      if (seen.before < o.min_rays || static_cast<double>(seen.before) < o.hidden_share * all) continue;
      least = growth;
      best = boxes[i];
      best->size(k) += growth;
      best->pose.t += 0.5 * down * growth * axis;
    }
    if (best) {
      boxes[i] = *best;
      ++grown;
    }
  }
  return grown;
}

}  // namespace ksmc::stdlib::tabletop::perception
