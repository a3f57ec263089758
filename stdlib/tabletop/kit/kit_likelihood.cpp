#include "stdlib/tabletop/kit/kit_likelihood.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "stdlib/tabletop/likelihood.h"

namespace ksmc::stdlib::tabletop::kit {

double object_log_likelihood(const Scene& scene, const SceneObject& object, const Pose& pose_in_table,
                             const blocks::KeypointGaussian& model) {
  const double s2 = model.sigma_px * model.sigma_px;
  const double norm = -std::log(2.0 * std::numbers::pi * s2);
  const double cap2 = model.outlier_px * model.outlier_px;
  const Pose cam = scene.table_in_camera.compose(pose_in_table);
  const Eigen::Matrix3d r = cam.rotation();
  double sum = 0.0;
  for (std::size_t i = 0; i < object.keypoints_model.size(); ++i) {
    const auto uv = project(scene.camera, r * object.keypoints_model[i] + cam.t);
    double d2;
    if (!uv) {
      if (!model.robust) return -std::numeric_limits<double>::infinity();
      d2 = cap2;
    } else {
      d2 = (*uv - object.keypoints_image[i]).squaredNorm();
      if (model.robust) d2 = std::min(d2, cap2);
    }
    sum += norm - d2 / (2.0 * s2);
  }
  return sum;
}

namespace {

blocks::KeypointGaussian scaled(const blocks::KeypointGaussian& declared, const PixelNoise& noise) {
  blocks::KeypointGaussian l = declared;
  const double scale = std::max(1.0, noise.sigma / declared.sigma_px);
  l.sigma_px *= scale;
  l.outlier_px *= scale;
  return l;
}

}  // namespace

blocks::KeypointGaussian scene_likelihood(const Scene& scene, const blocks::KeypointGaussian& declared) {
  return declared.sigma_from_scene ? scaled(declared, pixel_noise(scene)) : declared;
}

blocks::KeypointGaussian scene_likelihood(const Scene& scene, const blocks::KeypointGaussian& declared,
                                          const FitOf& fit_of) {
  return declared.sigma_from_scene ? scaled(declared, pixel_noise(scene, fit_of)) : declared;
}

}  // namespace ksmc::stdlib::tabletop::kit
