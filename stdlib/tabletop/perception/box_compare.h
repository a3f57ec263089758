// Errors between an estimated and a true box, modulo the box's symmetry: the estimate's
// axes are matched to the truth's by the signed axis permutation (24 proper rotations)
// that minimises the rotation angle, and its sizes are compared in that matching.
#pragma once

#include <Eigen/Geometry>

namespace ksmc::stdlib::tabletop::perception {

struct BoxError {
  double centre = 0.0;                                   // m
  double angle = 0.0;                                    // rad, after the best axis matching
  Eigen::Vector3d size = Eigen::Vector3d::Zero();        // estimate - truth per true axis [m]
  Eigen::Vector3i axis_of = Eigen::Vector3i(0, 1, 2);    // estimate axis matched to true axis k

  [[nodiscard]] double max_size() const { return size.cwiseAbs().maxCoeff(); }
};

// Rotations are box orientations (columns = axes) in one common frame.
BoxError compare_boxes(const Eigen::Vector3d& est_centre, const Eigen::Matrix3d& est_axes, const Eigen::Vector3d& est_size,
                       const Eigen::Vector3d& true_centre, const Eigen::Matrix3d& true_axes,
                       const Eigen::Vector3d& true_size);

}  // namespace ksmc::stdlib::tabletop::perception
