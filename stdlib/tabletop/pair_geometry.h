// Geometric facts about one pair of OBBs, computed once and shared by the
// contact and intersect extractors: exact distance (closest points), SAT
// penetration depth and axis, containment.
#pragma once

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

struct PairGeometry {
  double distance = 0.0;           // exact distance between the solids (0 if overlapping)
  double depth = 0.0;              // SAT penetration depth (0 if separated)
  bool overlapping = false;
  bool contained = false;          // one box entirely inside the other
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // gap direction (a→b) or SAT axis
};

PairGeometry pair_geometry(const Obb& a, const Obb& b);

}  // namespace ksmc::stdlib::tabletop
