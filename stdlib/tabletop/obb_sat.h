// Separating-axis test for two OBBs over the 15 candidate axes (3 + 3 face
// normals, 9 edge–edge cross products). Cross axes of (near-)parallel edges are
// skipped before normalising: boxes lying flat on a table have exactly parallel
// edges, and their cross product is noise.
#pragma once

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

struct SatResult {
  bool overlapping = false;  // no separating axis found
  // overlapping: minimum overlap over the tested axes = penetration depth (the
  // minimal translation distance for boxes). Separated: the largest gap found
  // (a lower bound of the true distance), as a positive number.
  double depth = 0.0;
  double gap = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit axis of minimum overlap / maximum gap
};

SatResult obb_sat(const Obb& a, const Obb& b, double parallel_eps = 1e-6);

}  // namespace ksmc::stdlib::tabletop
