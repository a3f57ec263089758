// Pinhole camera above the table and keypoint observations of box surfaces.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::tabletop_sim {

struct Camera {
  double fx = 615.0;
  double fy = 615.0;
  double cx = 320.0;
  double cy = 240.0;
  int width = 640;
  int height = 480;
};

struct CameraPlacement {
  double min_distance = 0.8;        // m from the look-at point on the table
  double max_distance = 1.2;
  double min_elevation = 0.5235988;  // rad (30 deg) of the viewing ray below the horizon
  double max_elevation = 1.0471976;  // rad (60 deg)
  double target_jitter = 0.03;       // m, look-at point around the table-frame origin
};

// Draws a camera pose in the table frame (OpenCV convention: x right, y down, z forward).
Pose draw_camera_pose(Rng& rng, const CameraPlacement& placement);

// Pixel of a table-frame point seen from `table_from_camera`; nullopt behind the camera.
std::optional<Eigen::Vector2d> project(const Camera& camera, const Pose& table_from_camera,
                                       const Eigen::Vector3d& point_in_table);

struct KeypointParams {
  int min_count = 10;
  int max_count = 30;
  double pixel_sigma = 1.0;    // px, Gaussian noise on every observation
  double outlier_rate = 0.05;  // fraction of observations displaced
  double outlier_min = 10.0;   // px
  double outlier_max = 50.0;   // px
  int tries_per_point = 40;    // surface samples tried per wanted keypoint
  double border = 2.0;         // px kept free at the image border
};

struct Keypoints {
  std::vector<Eigen::Vector3d> model;  // object frame (OBB centre), metres
  std::vector<Eigen::Vector2d> image;  // pixels
  int outliers = 0;
};

// Samples keypoints on the faces of `object` that face the camera, are inside the image and
// are not hidden behind any of `occluders`; projects them at the object's pose and adds
// pixel noise and outliers. Returns nullopt if fewer than params.min_count are visible.
std::optional<Keypoints> sample_keypoints(Rng& rng, const Camera& camera, const Pose& table_from_camera,
                                          const Box& object, std::span<const Box> occluders,
                                          const KeypointParams& params);

}  // namespace ksmc::tools::tabletop_sim
