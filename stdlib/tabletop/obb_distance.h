// Exact Euclidean distance between two solid OBBs with the closest points.
//
// For two disjoint convex polytopes a closest pair can always be chosen as
// vertex–solid, solid–vertex or edge–edge (face–face and edge–face closest sets
// contain such a pair on their boundary), so the minimum over the 8 + 8 vertex-to-box
// distances and the 12 × 12 segment–segment distances is the exact distance.
// Overlap is decided first by the separating-axis test (exact for the yes/no
// question); overlapping boxes have distance 0.
#pragma once

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

struct ClosestPoints {
  double distance = 0.0;            // 0 when the boxes overlap or touch
  Eigen::Vector3d on_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();
  bool overlapping = false;         // solids share interior or boundary points (SAT)
};

// Closest points of segments [p0,p1] and [q0,q1]; returns the squared distance.
double segment_segment_closest(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                               const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                               Eigen::Vector3d& on_p, Eigen::Vector3d& on_q);

ClosestPoints obb_closest_points(const Obb& a, const Obb& b);

}  // namespace ksmc::stdlib::tabletop
