// The keypoints' pixel noise, read off the scene: each observed object's keypoints are fitted
// (keypoint_fit.h, from its input estimate), and the image residuals at the fits, x and y of
// every keypoint of every object, give a robust scale, 1.4826 × median |residual| (the
// standard deviation of a zero-mean Gaussian; outliers and the few residuals of false
// estimates do not move a median). A detector's pixel noise differs from camera to camera and
// scene to scene; the keypoint likelihood's declared σ is its least
// (keypoints.gaussian sigma_from_scene, kit_likelihood.h).
#pragma once

#include <cstddef>
#include <functional>

#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct PixelNoise {
  double sigma = 0.0;          // [px] robust standard deviation of the residuals; 0: too few
  std::size_t residuals = 0;   // residuals seen (2 per keypoint of a fitted object)
};

// `fit_of(i)`: the keypoint fit of scene.objects[i] from its input estimate (a caller that
// caches fits, blocks::Scene::fit, passes them; the overload below computes them).
// Fewer than `min_residuals` residuals: sigma 0 (too little to judge by).
using FitOf = std::function<const KeypointFit&(std::size_t object)>;
PixelNoise pixel_noise(const Scene& scene, const FitOf& fit_of, std::size_t min_residuals = 40);
PixelNoise pixel_noise(const Scene& scene, std::size_t min_residuals = 40);

}  // namespace ksmc::stdlib::tabletop
