#include "stdlib/tabletop/obb_sat.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace ksmc::stdlib::tabletop {

namespace {

double radius_along(const Obb& box, const Eigen::Vector3d& axis) {
  double r = 0.0;
  for (int i = 0; i < 3; ++i) r += box.half[i] * std::abs(box.axes.col(i).dot(axis));
  return r;
}

}  // namespace

SatResult obb_sat(const Obb& a, const Obb& b, double parallel_eps) {
  const Eigen::Vector3d d = b.center - a.center;
  SatResult res;
  double min_overlap = std::numeric_limits<double>::infinity();
  double max_gap = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d min_axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d gap_axis = Eigen::Vector3d::UnitZ();

  auto test = [&](const Eigen::Vector3d& axis) {
    const double overlap = radius_along(a, axis) + radius_along(b, axis) - std::abs(d.dot(axis));
    if (overlap < min_overlap) {
      min_overlap = overlap;
      min_axis = axis;
    }
    if (-overlap > max_gap) {
      max_gap = -overlap;
      gap_axis = axis;
    }
  };

  for (int i = 0; i < 3; ++i) test(a.axes.col(i));
  for (int i = 0; i < 3; ++i) test(b.axes.col(i));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d c = a.axes.col(i).cross(b.axes.col(j));
      const double n = c.norm();
      if (n < parallel_eps) continue;  // parallel edges: axis already covered by face normals
      test(c / n);
    }
  }
  // Orient the reported axis from a to b.
  auto oriented = [&](Eigen::Vector3d axis) { return axis.dot(d) < 0 ? Eigen::Vector3d(-axis) : axis; };
  if (min_overlap >= 0.0) {
    res.overlapping = true;
    res.depth = min_overlap;
    res.axis = oriented(min_axis);
  } else {
    res.overlapping = false;
    res.gap = max_gap;
    res.axis = oriented(gap_axis);
  }
  return res;
}

}  // namespace ksmc::stdlib::tabletop
