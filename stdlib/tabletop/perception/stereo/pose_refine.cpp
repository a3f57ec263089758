#include "stdlib/tabletop/perception/stereo/pose_refine.h"

#include <cmath>

#include <Eigen/Dense>

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

// Pose perturbed by delta = (rotation vector, translation), applied on the left (camera frame).
Eigen::Isometry3d perturb(const Eigen::Isometry3d& pose, const Vec6& delta) {
  Eigen::Isometry3d d = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d w = delta.head<3>();
  if (w.norm() > 0.0) d.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  d.translation() = delta.tail<3>();
  return d * pose;
}

Eigen::VectorXd residuals(const StereoCalib& c, const Eigen::Isometry3d& pose, const std::vector<Eigen::Vector3d>& model,
                          const std::vector<Eigen::Vector2d>& left, const std::vector<Eigen::Vector2d>& right) {
  Eigen::VectorXd r(4 * static_cast<Eigen::Index>(model.size()));
  for (std::size_t i = 0; i < model.size(); ++i) {
    const Eigen::Vector3d pl = pose * model[i];
    const Eigen::Vector3d pr = c.r * pl + c.t;
    const Eigen::Vector3d ql = c.k_left * pl, qr = c.k_right * pr;
    const auto k = static_cast<Eigen::Index>(4 * i);
    r.segment<2>(k) = ql.head<2>() / ql.z() - left[i];
    r.segment<2>(k + 2) = qr.head<2>() / qr.z() - right[i];
  }
  return r;
}

double rms(const Eigen::VectorXd& r) { return r.size() ? std::sqrt(r.squaredNorm() / (0.5 * r.size())) : 0.0; }

}  // namespace

RefineResult refine_reprojection(const StereoCalib& calib, const Eigen::Isometry3d& pose,
                                 const std::vector<Eigen::Vector3d>& model, const std::vector<Eigen::Vector2d>& left,
                                 const std::vector<Eigen::Vector2d>& right, int iterations) {
  RefineResult out;
  out.pose = pose;
  Eigen::VectorXd r = residuals(calib, pose, model, left, right);
  out.rms_before = out.rms_after = rms(r);
  if (model.size() < 3) return out;
  double lambda = 1e-3;
  const double h = 1e-6;
  for (int it = 0; it < iterations; ++it) {
    Eigen::MatrixXd j(r.size(), 6);
    for (int k = 0; k < 6; ++k) {
      Vec6 d = Vec6::Zero();
      d[k] = h;
      j.col(k) = (residuals(calib, perturb(out.pose, d), model, left, right) -
                  residuals(calib, perturb(out.pose, -d), model, left, right)) /
                 (2.0 * h);
    }
    const Eigen::Matrix<double, 6, 6> jtj = j.transpose() * j;
    const Vec6 g = j.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 8 && !improved; ++tries) {
      Eigen::Matrix<double, 6, 6> a = jtj;
      a.diagonal() *= 1.0 + lambda;
      const Vec6 step = -a.ldlt().solve(g);
      const Eigen::Isometry3d cand = perturb(out.pose, step);
      const Eigen::VectorXd rc = residuals(calib, cand, model, left, right);
      if (rc.allFinite() && rc.squaredNorm() < r.squaredNorm()) {
        out.pose = cand;
        improved = step.norm() > 1e-10;
        r = rc;
        lambda = std::max(1e-7, lambda * 0.3);
        if (!improved) break;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) break;
  }
  out.rms_after = rms(r);
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
