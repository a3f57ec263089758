// Line of sight (obb.blocks): a box stands between the camera and another estimate's
// keypoints. A keypoint is a point of an object's surface the camera saw; nothing solid lies
// on its line of sight. So when box `front` lies across the lines of sight of several of
// object `seen`'s keypoints, one of the two estimates is wrong: `front` is not there, or the
// keypoints are not `seen`'s. Unlike intersect, this holds for boxes that do not touch: an
// estimate floating in front of a box whose keypoints were seen through it.
//
// Pose noise moves both boxes: `front` counts only by its core (shrunk by `margin` on every
// side; a box thinner than 2 margin blocks nothing), and a line of sight counts only up to
// `margin` before its keypoint (the keypoint's own surface, or a touching neighbour's).
#pragma once

#include <span>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop {

// How many of `model_points` (keypoints in the object frame of `seen_pose`) `front`'s core
// hides from `camera` (all in the table frame).
int keypoints_behind(const Obb& front, const Pose& seen_pose, std::span<const Eigen::Vector3d> model_points,
                     const Eigen::Vector3d& camera, double margin);

// At least `min_keypoints` and at least `min_fraction` of the keypoints are hidden.
bool extract_blocks(const Obb& front, const Pose& seen_pose, std::span<const Eigen::Vector3d> model_points,
                    const Eigen::Vector3d& camera, double margin, int min_keypoints, double min_fraction);

}  // namespace ksmc::stdlib::tabletop
