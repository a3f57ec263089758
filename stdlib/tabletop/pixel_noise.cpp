#include "stdlib/tabletop/pixel_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/likelihood.h"

namespace ksmc::stdlib::tabletop {

PixelNoise pixel_noise(const Scene& scene, std::size_t min_residuals) {
  std::vector<double> residuals;
  for (const auto& o : scene.objects) {
    const KeypointFit fit = fit_keypoints(scene, o);
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

}  // namespace ksmc::stdlib::tabletop
