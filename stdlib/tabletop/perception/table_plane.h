// The table: RANSAC plane (PCL SACSegmentation, least-squares refined), oriented so that
// the objects are above it, and a table frame built from the plane and the extent of its
// inliers (origin at the centre of their minimal rectangle, x along its first side).
#pragma once

#include <cstddef>
#include <string>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop::perception {

struct TableOptions {
  double distance_threshold = 0.01;  // m, RANSAC inlier band around the plane
  int max_iterations = 1000;
  std::size_t min_inliers = 100;     // fewer inliers than this (or than the fraction) = no plane
  double min_inlier_fraction = 0.15;
  double side_band = 0.4;            // m, points this far from the plane vote for "up"
  double extent_trim = 0.002;        // quantile trimmed off each side of the table extent
};

struct TableFit {
  Pose table_in_cloud;               // table frame (z = normal, top at z = 0) in the cloud frame
  Eigen::Vector2d extent = Eigen::Vector2d::Zero();  // sizes of the inliers along table x, y [m]
  std::size_t inliers = 0;
  double rms = 0.0;                  // inliers' RMS distance to the plane [m]
  // The sensor's depth noise at the table [m]: 1.4826 x the inliers' median distance to the
  // plane (a Gaussian's sigma; the feet of the objects, within the inlier band, and a
  // textured surface's tails move it less than they move the RMS).
  double noise = 0.0;
};

// Throws CloudError "<source>: no table plane: ..." when no plane holds enough points.
TableFit fit_table(const Points& cloud, const std::string& source, const TableOptions& options = {});

// Points mapped into the table frame.
Points to_table_frame(const Points& cloud, const Pose& table_in_cloud);

}  // namespace ksmc::stdlib::tabletop::perception
