// Final refinement of a detected object's pose on its inlier keypoints: Gauss-Newton
// (Levenberg damping) on the reprojection error in both images. The 3D-3D fit
// (object_pose.h) carries the triangulation's depth error (z^2 / (f b) per pixel of
// disparity, ~4 mm at 0.75 m); the image positions are ten times more precise laterally.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "stdlib/tabletop/perception/stereo/stereo_calib.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct RefineResult {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double rms_before = 0.0, rms_after = 0.0;  // px, over both images
};

// `model[i]` is seen at `left[i]` and `right[i]`; `pose` maps the object frame to the left camera.
RefineResult refine_reprojection(const StereoCalib& calib, const Eigen::Isometry3d& pose,
                                 const std::vector<Eigen::Vector3d>& model, const std::vector<Eigen::Vector2d>& left,
                                 const std::vector<Eigen::Vector2d>& right, int iterations = 15);

}  // namespace ksmc::stdlib::tabletop::perception::stereo
