// The table from stereo points, when the calibration does not give it: a RANSAC plane
// (seeded) through the stereo points no detected object claimed, with (almost) no point
// beyond it (the supporting plane, not a box top), its normal towards the camera; the table frame has z = that normal, its origin at the inliers' centroid projected
// onto the plane, x = the left camera's x axis projected onto the plane; the size is twice
// the inliers' largest |x| and |y| (the seen part of the table top).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct TableOptions {
  int iterations = 500;
  double tolerance = 0.012;  // m, point-to-plane (stereo depth noise ~6 mm at 1 m)
  int min_inliers = 50;
  double min_share = 0.1;    // of the candidate points
  double max_below = 0.03;   // share of the points allowed beyond the plane (seen from the camera)
  double thickness = 0.05;   // m
  std::uint64_t seed = 7;
};

struct StereoTable {
  Pose table_in_left;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  int inliers = 0, candidates = 0;
  double rms = 0.0;  // m
};

// `points` in the left camera frame. nullopt when no plane holds enough of them.
std::optional<StereoTable> table_from_points(const std::vector<Eigen::Vector3d>& points, const TableOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception::stereo
