// Evaluation against ground-truth boxes: read obb_world.json (HOPE frame), match the
// estimated boxes to the true ones (through a rigid registration when the frames differ)
// and report per-object centre, angle and size errors (box_compare.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stdlib/tabletop/perception/box_compare.h"
#include "stdlib/tabletop/perception/registration.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::perception {

struct TruthBox {
  std::string name;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

// obb_world.json: {"objects":[{"class", "center_m", "R_rowmajor", "size_m"}]}. Throws
// CloudError "<file>: objects[i].<field>: ..." on malformed input.
std::vector<TruthBox> read_obb_world(const std::filesystem::path& path);

// The scene's objects as boxes in the camera (cloud) frame.
std::vector<TruthBox> camera_frame_boxes(const Scene& scene);

struct ObjectError {
  int estimate = -1;  // index into the estimates, -1 when the true box was not found
  BoxError error;     // in the truth frame
};

struct TruthReport {
  Registration registration;        // estimates' frame -> truth frame, with the matching
  std::vector<ObjectError> objects; // one per true box
  int missed = 0;                   // true boxes without an estimate
  int spurious = 0;                 // estimates without a true box
};

// Frames differ: registers the estimate centres to the true centres (register_unmatched).
TruthReport evaluate_registered(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth, double gate);
// Known transform (estimates' frame -> truth frame): nearest-centre matching under it.
TruthReport evaluate_with_transform(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth,
                                    const Eigen::Isometry3d& transform, double gate);
// Matching given (registration.match per estimate, registration.source_to_target).
TruthReport evaluate_matched(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth,
                             Registration registration);
// Same frame: nearest-centre matching only.
TruthReport evaluate_same_frame(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth, double gate);

}  // namespace ksmc::stdlib::tabletop::perception
