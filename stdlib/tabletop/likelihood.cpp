#include "stdlib/tabletop/likelihood.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace ksmc::stdlib::tabletop {

std::optional<Eigen::Vector2d> project(const Camera& camera, const Eigen::Vector3d& p, double min_depth) {
  if (!(p.z() >= min_depth)) return std::nullopt;
  return Eigen::Vector2d(camera.fx * p.x() / p.z() + camera.cx, camera.fy * p.y() / p.z() + camera.cy);
}

double keypoint_log_likelihood(const Scene& scene, const SceneObject& o, const Pose& pose_in_table,
                               const KeypointLikelihoodParams& params) {
  if (!(params.sigma_x_px > 0.0) || !(params.sigma_y_px > 0.0))
    throw std::invalid_argument("keypoint likelihood: sigma must be > 0");
  if (params.robust && !(params.outlier_weight > 0.0 && params.outlier_weight < 1.0))
    throw std::invalid_argument("keypoint likelihood: outlier_weight must be in (0, 1)");
  const Eigen::Isometry3d cam_from_obj = scene.table_in_camera.compose(pose_in_table).isometry();
  const double log_norm = -std::log(2.0 * std::numbers::pi * params.sigma_x_px * params.sigma_y_px);
  const double area = static_cast<double>(scene.camera.width) * static_cast<double>(scene.camera.height);
  const double log_out = std::log(params.outlier_weight / area);
  const double log_in_w = std::log1p(-params.outlier_weight);
  double sum = 0.0;
  for (std::size_t i = 0; i < o.keypoints_model.size(); ++i) {
    const auto uv = project(scene.camera, cam_from_obj * o.keypoints_model[i], params.min_depth);
    if (!uv) {
      if (!params.robust) return -std::numeric_limits<double>::infinity();
      sum += log_out;
      continue;
    }
    const double dx = (o.keypoints_image[i].x() - uv->x()) / params.sigma_x_px;
    const double dy = (o.keypoints_image[i].y() - uv->y()) / params.sigma_y_px;
    const double log_gauss = log_norm - 0.5 * (dx * dx + dy * dy);
    if (!params.robust) {
      sum += log_gauss;
    } else {
      // log(exp(a) + exp(b)) without overflow.
      const double a = log_in_w + log_gauss;
      const double hi = std::max(a, log_out);
      sum += hi + std::log(std::exp(a - hi) + std::exp(log_out - hi));
    }
  }
  return sum;
}

double scene_log_likelihood(const Scene& scene, const KeypointLikelihoodParams& params) {
  double sum = 0.0;
  for (const auto& o : scene.objects) sum += keypoint_log_likelihood(scene, o, o.pose, params);
  return sum;
}

}  // namespace ksmc::stdlib::tabletop
