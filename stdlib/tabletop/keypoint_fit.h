// The pose the keypoints imply (seed §4.9, data-driven proposals): a Gauss-Newton fit of one
// object's pose to its matched keypoints, and the Laplace approximation of the keypoint
// likelihood around it, N(mean, covariance) in the tangent coordinates of a pose
// (δt = t − t_mean in the table frame, δω = log(q · q_meanᵀ) applied on the left, as
// pose_proposal.h perturbs). The fit is a function of the observations alone (keypoints,
// camera, table pose) and of the estimate it starts from, never of the sampler's state:
// an independence proposal drawn from it has an exact density (pose.fit).
//
// Residuals beyond `outlier_px` after a first fit are dropped (the robust likelihood's
// outliers). A weak Gaussian pull towards the input estimate (prior_sigma_t / _r) keeps the
// directions few keypoints do not constrain near the estimate.
#pragma once

#include <random>

#include <Eigen/Core>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct KeypointFitParams {
  double sigma_px = 1.0;
  double outlier_px = 5.0;     // residuals beyond this after the first fit are outliers
  double prior_sigma_t = 0.02; // m, pull towards the input estimate
  double prior_sigma_r = 0.17; // rad (about 10 deg)
  int iterations = 12;         // Gauss-Newton steps per pass (two passes)
};

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

struct KeypointFit {
  bool ok = false;          // false: fewer than 4 usable keypoints or a singular system
  Pose mean;                // table frame
  Matrix6d covariance = Matrix6d::Identity();  // [δt (m), δω (rad)]
  int inliers = 0;
  // Standard deviation of the height (table-frame z) of the box's lowest point.
  double bottom_sigma = 0.0;
};

KeypointFit fit_keypoints(const Scene& scene, const SceneObject& object, const KeypointFitParams& params = {});

// Tangent coordinates of `pose` relative to `mean` (δt, δω).
Vector6d pose_delta(const Pose& mean, const Pose& pose);
// `mean` moved by tangent coordinates `d`.
Pose pose_plus(const Pose& mean, const Vector6d& d);

// Log density of `pose` under N(fit.mean, scale² · fit.covariance) in tangent coordinates,
// with the Haar-measure Jacobian of the rotation part (exact on SE(3) up to a constant).
double fit_log_density(const KeypointFit& fit, double scale, const Pose& pose);
// A pose drawn from that density.
Pose sample_fit(const KeypointFit& fit, double scale, std::mt19937_64& rng);

}  // namespace ksmc::stdlib::tabletop
