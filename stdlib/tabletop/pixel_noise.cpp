#include "stdlib/tabletop/pixel_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stdlib/tabletop/likelihood.h"

namespace ksmc::stdlib::tabletop {

PixelNoise pixel_noise(const Scene& scene, const FitOf& fit_of, std::size_t min_residuals) {
  std::vector<double> residuals;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.keypoints_model.empty()) continue;
    const KeypointFit& fit = fit_of(i);
    if (!fit.ok) continue;
    const Eigen::Isometry3d cam = scene.table_in_camera.compose(fit.mean).isometry();
    for (std::size_t k = 0; k < o.keypoints_model.size(); ++k) {
      const auto uv = project(scene.camera, cam * o.keypoints_model[k]);
      if (!uv) continue;
      residuals.push_back(std::abs(uv->x() - o.keypoints_image[k].x()));
      residuals.push_back(std::abs(uv->y() - o.keypoints_image[k].y()));
    }
  }
  PixelNoise out;
  out.residuals = residuals.size();
  if (residuals.size() < min_residuals || residuals.empty()) return out;
  const auto mid = residuals.begin() + static_cast<std::ptrdiff_t>(residuals.size() / 2);
  std::nth_element(residuals.begin(), mid, residuals.end());
  out.sigma = 1.4826 * *mid;
  return out;
}

PixelNoise pixel_noise(const Scene& scene, std::size_t min_residuals) {
  KeypointFit last;
  return pixel_noise(
      scene, [&](std::size_t i) -> const KeypointFit& { return last = fit_keypoints(scene, scene.objects[i]); },
      min_residuals);
}

}  // namespace ksmc::stdlib::tabletop
