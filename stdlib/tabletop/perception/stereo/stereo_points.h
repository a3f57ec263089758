// Stereo-consistent SIFT keypoints (Alg. 2 line 1, seed Fig. 4.13): SIFT (cv::SIFT) on both
// images, every left keypoint matched to the right keypoints within `epipolar_tolerance`
// pixels of its epipolar line (any calibrated rig: the distance is taken with F), best by
// descriptor distance with a ratio test against the second best and a left-right
// cross-check, then triangulated (linear, left camera frame) and kept when in front of both
// cameras and reprojected within tolerance.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "stdlib/tabletop/perception/stereo/stereo_calib.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct StereoOptions {
  int max_features = 0;              // per image, 0 = all
  double contrast_threshold = 0.04;  // SIFT
  double epipolar_tolerance = 1.5;   // px
  double ratio = 0.8;                // best / second-best descriptor distance
  double min_depth = 0.1;            // m
  double max_depth = 5.0;
  double reprojection_tolerance = 2.0;  // px, in both images
};

struct StereoPoints {
  std::vector<Eigen::Vector2d> left, right;  // pixels
  std::vector<Eigen::Vector3d> point;        // left camera frame, metres
  cv::Mat left_descriptors, right_descriptors;  // CV_32F, one row per point
  std::size_t left_keypoints = 0, right_keypoints = 0;
};

// Grey 8-bit images of calib.width x calib.height (checked by the caller).
StereoPoints stereo_points(const cv::Mat& left, const cv::Mat& right, const StereoCalib& calib,
                           const StereoOptions& options = {});

// Linear triangulation of one correspondence (left camera frame).
Eigen::Vector3d triangulate(const StereoCalib& calib, const Eigen::Vector2d& left, const Eigen::Vector2d& right);

}  // namespace ksmc::stdlib::tabletop::perception::stereo
