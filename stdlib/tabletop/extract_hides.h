// Covered surface (obb.hides): a box stands in front of the part of another estimate's surface
// that faces the camera, and that part, were the estimate a real box, would show keypoints.
// With `obb.blocks` it tells which of two estimates that cut into each other is false. If the
// box behind were real, the camera would see its keypoints through the false box in front
// (blocks holds). If the box behind is the false one, the real box in front hides that part,
// and no keypoint lies there (blocks does not hold although hides does).
//
// How much would show: the estimate's faces towards the camera are sampled on a grid, each
// sample weighted by its face's area times the cosine to the camera (the face's area as the
// camera sees it). Of that, the share `covered` lies behind the front box's core (shrunk by
// `margin`, the line of sight stopping `margin` before the face, as in extract_blocks.h). The
// keypoints the estimate has elsewhere set the density: n keypoints on the uncovered share
// 1 - covered predict n * covered / (1 - covered) on the covered part.
#pragma once

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// The share of `seen`'s camera-facing surface (projected area) behind `front`'s core, seen from
// `camera` (table frame); 0 when no face of `seen` faces the camera.
double covered_share(const Obb& front, const Obb& seen, const Eigen::Vector3d& camera, double margin);

// The covered part would show at least `min_expected` of `seen`'s `keypoints` (see above).
bool extract_hides(const Obb& front, const Obb& seen, int keypoints, const Eigen::Vector3d& camera, double margin,
                   double min_expected);

}  // namespace ksmc::stdlib::tabletop
