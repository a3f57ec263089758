#include "stdlib/tabletop/keypoint_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Cholesky>

#include "stdlib/tabletop/likelihood.h"

namespace ksmc::stdlib::tabletop {

namespace {

Eigen::Quaterniond exp_so3(const Eigen::Vector3d& w) {
  const double a = w.norm();
  if (a < 1e-12) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, w / a));
}

Eigen::Vector3d log_so3(const Eigen::Quaterniond& q) {
  Eigen::AngleAxisd aa(q.normalized());
  double a = aa.angle();
  Eigen::Vector3d axis = aa.axis();
  if (a > std::numbers::pi) {
    a = 2.0 * std::numbers::pi - a;
    axis = -axis;
  }
  return a * axis;
}

// Whitened residuals (2 per used keypoint) at pose `p`; false when a point does not project.
bool residuals(const Scene& scene, const SceneObject& o, const Pose& p, const std::vector<char>& use, double sigma,
               Eigen::VectorXd& r) {
  const Eigen::Isometry3d cam = scene.table_in_camera.compose(p).isometry();
  r.resize(2 * static_cast<Eigen::Index>(std::count(use.begin(), use.end(), 1)));
  Eigen::Index k = 0;
  for (std::size_t i = 0; i < o.keypoints_model.size(); ++i) {
    if (!use[i]) continue;
    const auto uv = project(scene.camera, cam * o.keypoints_model[i]);
    if (!uv) return false;
    r(k++) = (uv->x() - o.keypoints_image[i].x()) / sigma;
    r(k++) = (uv->y() - o.keypoints_image[i].y()) / sigma;
  }
  return true;
}

// Log of the Haar-measure density factor of exponential coordinates: θ² / (2 (1 − cos θ)).
double log_haar_jacobian(const Eigen::Vector3d& w) {
  const double a = w.norm();
  if (a < 1e-6) return 0.0;
  return std::log(a * a / (2.0 * (1.0 - std::cos(a))));
}

}  // namespace

Vector6d pose_delta(const Pose& mean, const Pose& pose) {
  Vector6d d;
  d.head<3>() = pose.t - mean.t;
  d.tail<3>() = log_so3(pose.q * mean.q.conjugate());
  return d;
}

Pose pose_plus(const Pose& mean, const Vector6d& d) {
  Pose p;
  p.t = mean.t + d.head<3>();
  p.q = (exp_so3(d.tail<3>()) * mean.q).normalized();
  return p;
}

KeypointFit fit_keypoints(const Scene& scene, const SceneObject& o, const KeypointFitParams& params) {
  KeypointFit fit;
  const std::size_t n = o.keypoints_model.size();
  if (n < 4) return fit;
  std::vector<char> use(n, 1);
  Matrix6d prior = Matrix6d::Zero();
  prior.diagonal() << Eigen::Vector3d::Constant(1.0 / (params.prior_sigma_t * params.prior_sigma_t)),
      Eigen::Vector3d::Constant(1.0 / (params.prior_sigma_r * params.prior_sigma_r));
  const Pose start = o.pose;
  Pose p = start;
  Matrix6d info = prior;
  for (int pass = 0; pass < 2; ++pass) {
    for (int it = 0; it < params.iterations; ++it) {
      Eigen::VectorXd r;
      if (!residuals(scene, o, p, use, params.sigma_px, r)) return fit;
      Eigen::MatrixXd jac(r.size(), 6);
      for (int j = 0; j < 6; ++j) {  // central differences in tangent coordinates
        const double h = 1e-5;  // m and rad
        Vector6d d = Vector6d::Zero();
        d(j) = h;
        Eigen::VectorXd rp, rm;
        if (!residuals(scene, o, pose_plus(p, d), use, params.sigma_px, rp) ||
            !residuals(scene, o, pose_plus(p, -d), use, params.sigma_px, rm))
          return fit;
        jac.col(j) = (rp - rm) / (2.0 * h);
      }
      info = jac.transpose() * jac + prior;
      const Vector6d to_start = pose_delta(p, start);
      const Vector6d g = jac.transpose() * r - prior * to_start;
      const Eigen::LDLT<Matrix6d> ldlt(info);
      if (ldlt.info() != Eigen::Success) return fit;
      const Vector6d step = -ldlt.solve(g);
      if (!step.allFinite()) return fit;
      p = pose_plus(p, step);
      if (step.head<3>().norm() < 1e-7 && step.tail<3>().norm() < 1e-7) break;
    }
    if (pass == 1) break;
    // Drop outliers of the first fit (keep at least 4 keypoints).
    Eigen::VectorXd r;
    std::vector<char> all(n, 1);
    if (!residuals(scene, o, p, all, 1.0, r)) return fit;
    std::vector<char> keep(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      keep[i] = std::hypot(r(2 * static_cast<Eigen::Index>(i)), r(2 * static_cast<Eigen::Index>(i) + 1)) <= params.outlier_px;
    if (std::count(keep.begin(), keep.end(), 1) >= 4) use = keep;
  }
  fit.inliers = static_cast<int>(std::count(use.begin(), use.end(), 1));
  fit.mean = p;
  fit.covariance = info.inverse();
  if (!fit.covariance.allFinite()) return fit;
  // Height of the lowest vertex: dz = δt_z + (δω × v)_z for the lowest vertex v (relative to the centre).
  const Obb box = Obb::from_pose(p, o.size);
  Eigen::Vector3d lowest = Eigen::Vector3d::Zero();
  double zmin = std::numeric_limits<double>::infinity();
  for (int sx = -1; sx <= 1; sx += 2)
    for (int sy = -1; sy <= 1; sy += 2)
      for (int sz = -1; sz <= 1; sz += 2) {
        const Eigen::Vector3d v = box.axes * Eigen::Vector3d(sx * box.half.x(), sy * box.half.y(), sz * box.half.z());
        if (v.z() < zmin) zmin = v.z(), lowest = v;
      }
  Vector6d a = Vector6d::Zero();  // dz = a · δ
  a(2) = 1.0;
  a.tail<3>() = lowest.cross(Eigen::Vector3d::UnitZ());  // (δω × v)_z = δω · (v × e_z)
  fit.bottom_sigma = std::sqrt(std::max(0.0, a.dot(fit.covariance * a)));
  fit.ok = true;
  return fit;
}

double fit_log_density(const KeypointFit& fit, double scale, const Pose& pose) {
  const Vector6d d = pose_delta(fit.mean, pose);
  const Matrix6d cov = scale * scale * fit.covariance;
  const Eigen::LLT<Matrix6d> llt(cov);
  const Vector6d z = llt.matrixL().solve(d);
  double log_det = 0.0;
  for (int i = 0; i < 6; ++i) log_det += 2.0 * std::log(llt.matrixL()(i, i));
  return -0.5 * z.squaredNorm() - 0.5 * log_det - 3.0 * std::log(2.0 * std::numbers::pi) + log_haar_jacobian(d.tail<3>());
}

Pose sample_fit(const KeypointFit& fit, double scale, std::mt19937_64& rng) {
  auto uniform = [&rng] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };
  Vector6d z;
  for (int i = 0; i < 6; ++i)  // Box-Muller, portable across standard libraries
    z(i) = std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * std::numbers::pi * uniform());
  const Eigen::LLT<Matrix6d> llt(scale * scale * fit.covariance);
  return pose_plus(fit.mean, llt.matrixL() * z);
}

}  // namespace ksmc::stdlib::tabletop
