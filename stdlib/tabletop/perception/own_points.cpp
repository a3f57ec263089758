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
  const Obb box = Obb::from_pose(boxes[i].pose, boxes[i].size);
  if (in_cluster == 1) {
    if (!options.not_below) return cluster;
    Points own;
    for (const auto& p : cluster)
      if (p.z() >= box.min_z() - options.layer_margin) own.push_back(p);
    return own;
  }
  // upper stands on lower: its bottom at lower's top, their footprints overlapping (one of 5 x 5
  // points spanning either footprint, edges included, over the other). Not only upper's centre:
  // a box lying across the strip the front end found of a lower box (its visible side) has its
  // centre behind it, and a strip can pass between a wide box's points.
  const auto over = [&](const Obb& a, const Obb& b, double z) {  // a's footprint points over b, at height z
    for (int s = 0; s < 5; ++s)
      for (int t = 0; t < 5; ++t) {
        const Eigen::Vector3d p =
            a.center + (s / 2.0 - 1.0) * a.half.x() * a.axes.col(0) + (t / 2.0 - 1.0) * a.half.y() * a.axes.col(1);
        if (b.contains(Eigen::Vector3d(p.x(), p.y(), z), options.stand_gap)) return true;
      }
    return false;
  };
  const auto stands_on = [&](const Obb& upper, const Obb& lower) {
    if (std::abs(upper.min_z() - lower.max_z()) > options.stand_gap) return false;
    return over(upper, lower, lower.max_z()) || over(lower, upper, upper.min_z());
  };
  double top = std::numeric_limits<double>::infinity(), bottom = -top;
  std::vector<Obb> others;  // the cluster's other boxes
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (j == i || cluster_of[j] != c) continue;
    const Obb& other = others.emplace_back(Obb::from_pose(boxes[j].pose, boxes[j].size));
    if (stands_on(other, box)) top = box.max_z() + options.layer_margin;
    if (stands_on(box, other)) bottom = box.min_z() - options.layer_margin;
  }
  if (options.not_below) bottom = box.min_z() - options.layer_margin;
  // Nearer another box by more than the layer margin: that box's point (options.nearest).
  const auto nearer_another = [&](const Eigen::Vector3d& p) {
    if (!options.nearest) return false;
    const double mine = box.distance_to(p) - options.layer_margin;
    for (const Obb& other : others)
      if (other.distance_to(p) < mine) return true;
    return false;
  };
  Points own;
  for (const auto& p : cluster)
    if (box.contains(p, options.margin) && p.z() <= top && p.z() >= bottom && !nearer_another(p)) own.push_back(p);
  return own;
}

}  // namespace ksmc::stdlib::tabletop::perception
