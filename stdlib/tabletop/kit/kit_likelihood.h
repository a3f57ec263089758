// keypoints.gaussian(sigma, robust, outlier_px) of stdlib/tabletop.ksm, eq. 4.4.
//
// Each matched keypoint i of an object contributes, with r_i the pixel residual between
// the observed and the projected keypoint (isotropic σ):
//   plain:   log N2(r_i; σ) = −log(2πσ²) − |r_i|²/(2σ²)
//   robust:  −log(2πσ²) − min(|r_i|, outlier_px)²/(2σ²)
// i.e. the robust variant caps a residual beyond `outlier_px` at the constant penalty of
// a residual of exactly `outlier_px` (what the .ksm signature documents). A keypoint that
// does not project (behind the camera) makes the plain likelihood −∞ and costs the
// outlier penalty in the robust one. An object without keypoints contributes 0.
#pragma once

#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/pixel_noise.h"
#include "stdlib/tabletop/pose.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::kit {

double object_log_likelihood(const Scene& scene, const SceneObject& object, const Pose& pose_in_table,
                             const blocks::KeypointGaussian& model);

// The likelihood a scene is scored with: `declared`, or, with sigma_from_scene, σ and
// outlier_px both multiplied by max(1, scene pixel noise / σ) (pixel_noise.h: 1.4826 × median
// |residual| at the objects' keypoint fits; unchanged when the scene has fewer than 40
// residuals). A function of the observations alone, so every chain of a run, and the model
// restored to the best state, score with the same σ.
// `fit_of`: the objects' keypoint fits when the caller has them cached (pixel_noise.h).
blocks::KeypointGaussian scene_likelihood(const Scene& scene, const blocks::KeypointGaussian& declared);
blocks::KeypointGaussian scene_likelihood(const Scene& scene, const blocks::KeypointGaussian& declared,
                                          const FitOf& fit_of);

}  // namespace ksmc::stdlib::tabletop::kit
