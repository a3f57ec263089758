// Calibration of a stereo rig (stereo.yaml, cv::FileStorage YAML): intrinsics of both
// cameras, the right camera's pose relative to the left one (x_right = R x_left + t), the
// image size, and optionally where the table is: the table frame in the left camera frame
// (the rig's extrinsic calibration to the table). Without it the front end fits the table
// plane to the stereo points (stereo_table.h).
//
//   %YAML:1.0
//   image_width: 640
//   image_height: 480
//   K_left: !!opencv-matrix {rows: 3, cols: 3, dt: d, data: [fx, 0, cx, 0, fy, cy, 0, 0, 1]}
//   K_right: ...
//   R: 3x3, t: 3x1 (metres)
//   table_R: 3x3, table_t: 3x1 (optional, both or neither: table frame in the left camera frame)
//   table_size: [x, y, thickness] (optional, metres)
#pragma once

#include <filesystem>
#include <optional>

#include <Eigen/Core>

#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct StereoCalib {
  int width = 0, height = 0;
  Eigen::Matrix3d k_left = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d k_right = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();  // x_right = r x_left + t
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  std::optional<Pose> table_in_left;  // none: the table is fitted to the stereo points
  Eigen::Vector3d table_size{1.2, 0.8, 0.05};

  // Fundamental matrix: x_right^T F x_left = 0 (pixels).
  [[nodiscard]] Eigen::Matrix3d fundamental() const;
};

// Throws StereoError naming the file (missing, not YAML, a missing or malformed entry,
// a non-rotation R, a zero baseline).
StereoCalib load_calib(const std::filesystem::path& file);
void save_calib(const std::filesystem::path& file, const StereoCalib& calib);

}  // namespace ksmc::stdlib::tabletop::perception::stereo
