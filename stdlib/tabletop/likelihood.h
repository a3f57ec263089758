// Keypoint reprojection likelihood, seed eq. (4.4), in log space.
//
// The model keypoints of an object (object/OBB frame) are moved by the pose under
// test (table frame), taken to the camera frame by the table pose and projected with
// the pinhole model; each observed image keypoint contributes an independent
// Gaussian in u and v (σ = 1 px by default):
//   log p = Σ_i [ −log(2π σx σy) − (u_i − û_i)²/(2σx²) − (v_i − v̂_i)²/(2σy²) ].
// Robust variant: each keypoint is an inlier with probability 1 − w (the Gaussian
// above) or an outlier with probability w, uniform over the image area W·H:
//   log p_i = log((1 − w) N(u_i, v_i) + w / (W·H)),
// so one wrong match costs at most −log(w / (W·H)) instead of growing quadratically.
#pragma once

#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct KeypointLikelihoodParams {
  double sigma_x_px = 1.0;
  double sigma_y_px = 1.0;
  bool robust = false;
  double outlier_weight = 0.05;  // w of the robust mixture, in (0, 1)
  double min_depth = 1e-3;       // points closer than this to the camera plane do not project [m]
};

// Pinhole projection of a camera-frame point; nullopt when z < min_depth.
std::optional<Eigen::Vector2d> project(const Camera& camera, const Eigen::Vector3d& p_camera, double min_depth = 1e-3);

// Log-likelihood of object `o`'s keypoints if it had pose `pose_in_table`.
// Gaussian: −inf when a keypoint cannot be projected. 0 for an object without keypoints.
double keypoint_log_likelihood(const Scene& scene, const SceneObject& o, const Pose& pose_in_table,
                               const KeypointLikelihoodParams& params = {});
// Σ over all objects at their current poses.
double scene_log_likelihood(const Scene& scene, const KeypointLikelihoodParams& params = {});

}  // namespace ksmc::stdlib::tabletop
