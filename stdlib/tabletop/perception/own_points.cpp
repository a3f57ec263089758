#include "stdlib/tabletop/perception/own_points.h"

#include <cmath>
#include <limits>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop::perception {

Points own_points(const std::vector<UprightBox>& boxes, const std::vector<std::size_t>& cluster_of, std::size_t i,
                  const Points& cluster, const OwnPointsOptions& options) {
  const std::size_t c = cluster_of.at(i);
  std::size_t in_cluster = 0;
  for (const std::size_t k : cluster_of) in_cluster += k == c ? 1 : 0;
  if (in_cluster == 1) return cluster;
  const Obb box = Obb::from_pose(boxes[i].pose, boxes[i].size);
  // upper stands on lower: its bottom at lower's top, its centre over lower's footprint.
  const auto stands_on = [&](const Obb& upper, const Obb& lower) {
    return std::abs(upper.min_z() - lower.max_z()) <= options.stand_gap &&
           lower.contains(Eigen::Vector3d(upper.center.x(), upper.center.y(), lower.max_z()), options.stand_gap);
  };
  double top = std::numeric_limits<double>::infinity(), bottom = -top;
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (j == i || cluster_of[j] != c) continue;
    const Obb other = Obb::from_pose(boxes[j].pose, boxes[j].size);
    if (stands_on(other, box)) top = box.max_z() + options.layer_margin;
    if (stands_on(box, other)) bottom = box.min_z() - options.layer_margin;
  }
  Points own;
  for (const auto& p : cluster)
    if (box.contains(p, options.margin) && p.z() <= top && p.z() >= bottom) own.push_back(p);
  return own;
}

}  // namespace ksmc::stdlib::tabletop::perception
