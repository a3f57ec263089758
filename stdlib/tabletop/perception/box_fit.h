// One box per cluster with one axis along the table normal: the minimal-area rectangle of
// the footprint (the points projected on the table) and the height of the top surface.
// The box stands on the table unless the cluster clearly starts above it.
#pragma once

#include <cmath>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop::perception {

struct BoxFitOptions {
  double footprint_trim = 0.003;  // quantile pulled in on each footprint side (noise points)
  double top_quantile = 0.995;    // robust highest point ...
  double top_band = 0.006;        // m; the top is the median height of the points this far below it
  double float_gap = 0.03;        // m; a cluster whose 1 % height quantile is higher starts there
  double min_size = 0.005;        // m, lower bound of every extent
  bool side_faces_only = false;   // the points are side faces (no top): footprint by faces_rect
  bool wall_yaw = true;           // a large vertical face turns the footprint to its normal
  double wall_share = 0.2;        // ... when it holds this share of the points (on a sparse copy)
  double wall_voxel = 0.008;      // m, the sparse copy's voxel
  double wall_tilt_deg = 5.0;     // a face this close to vertical is a wall
  double wall_agree_deg = 1.0;    // the minimal rectangle stays when a side is this close to the wall
  double wall_beyond = 0.05;      // the footprint ends at the wall unless more points than this lie beyond it
};

struct UprightBox {
  Pose pose;                      // table frame; axis 2 = table normal, axis 0 at yaw in [0, 90 deg)
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

// Whether `box` stands upright (axis 2 along the table normal; a tilted fit's is not), and the
// height of its bottom face (upright boxes).
inline bool is_upright(const UprightBox& box) {
  return std::abs((box.pose.q * Eigen::Vector3d::UnitZ()).z()) > 1.0 - 1e-9;
}
inline double bottom_height(const UprightBox& box) { return box.pose.t.z() - 0.5 * box.size.z(); }

// `points` in the table frame (z up, top at 0), at least one point.
UprightBox fit_upright_box(const Points& points, const BoxFitOptions& options = {});

// The height of the top face fit_upright_box gives `points` (at least one).
double top_height(const Points& points, const BoxFitOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
