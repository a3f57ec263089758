// Geometric facts about one pair of OBBs, computed once and shared by the
// contact and intersect extractors: exact distance (closest points), SAT
// penetration depth and axis, containment.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

struct PairGeometry {
  double distance = 0.0;           // distance between the solids (0 if overlapping), exact if distance_exact
  bool distance_exact = true;      // false: `distance` is the SAT lower bound (gap beyond exact_below)
  double depth = 0.0;              // SAT penetration depth (0 if separated)
  bool overlapping = false;
  bool contained = false;          // one box entirely inside the other
  // The boxes' z-intervals [min_z, max_z] are offset like a stack: one starts and ends
  // strictly above the other. A thin box pushed sideways into another at mid-height is
  // not stacked (its z-interval lies inside the other's).
  bool stacked = false;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // gap direction (a→b) or SAT axis
};

// `exact_below`: when the SAT gap (a lower bound of the distance) already exceeds
// it, the exact closest-point enumeration is skipped and the gap is reported with
// distance_exact = false. Extractors pass their largest contact tolerance, so the
// contact decision is unaffected.
PairGeometry pair_geometry(const Obb& a, const Obb& b,
                           double exact_below = std::numeric_limits<double>::infinity());

}  // namespace ksmc::stdlib::tabletop
