// Synthesised stereo pairs for the stereo front end's tests and benchmark: textured boxes
// with known poses rendered into a calibrated rig (left camera + baseline along its x
// axis, rectified), one ray per sub-pixel (2 x 2 per pixel), nearest face among the boxes
// and the table top, its texture sampled bilinearly, Lambertian shading from a fixed light,
// Gaussian pixel noise. Textures are procedural (random shapes, deterministic per seed) so
// SIFT finds keypoints; write_object_folder writes a box as an object-database folder.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "stdlib/tabletop/perception/stereo/stereo_calib.h"
#include "stdlib/tabletop/pose.h"

namespace ksmc::tools::stereo_synth {

using stdlib::tabletop::Pose;
using stdlib::tabletop::perception::stereo::StereoCalib;

// Grey texture of w x h pixels full of random filled shapes and lines (seeded).
cv::Mat procedural_texture(int w, int h, std::uint64_t seed);

inline constexpr double kTexturePixelsPerMetre = 2000.0;

struct TexturedBox {
  std::string name;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // full extents, metres
  Pose pose;                                       // table frame (z up, table top at z = 0)
  std::array<cv::Mat, 6> faces;                    // per face (object_db.h order); empty = plain grey
  int plain_grey = 128;                            // grey of an untextured face
};

// A box with six procedural face textures (kTexturePixelsPerMetre).
TexturedBox textured_box(const std::string& name, const Eigen::Vector3d& size, const Pose& pose, std::uint64_t seed);

struct Rig {
  int width = 640, height = 480;
  double f = 615.0;            // px, both cameras
  double baseline = 0.08;      // m, right camera at +baseline along the left camera's x axis
  Pose table_from_left;        // left camera pose in the table frame (OpenCV axes)
  Eigen::Vector2d table_half{0.6, 0.4};
  double noise = 1.5;          // grey levels
};

// A left camera looking at the table origin from `distance`, `elevation` (rad below the
// horizon) and `azimuth` (rad about z; 0 = from -y).
Pose look_at_table(double distance, double elevation, double azimuth);

StereoCalib rig_calib(const Rig& rig);

struct StereoPair {
  cv::Mat left, right;  // CV_8U
};

StereoPair render_pair(const Rig& rig, const std::vector<TexturedBox>& boxes, std::uint64_t seed);

// A box standing upright on the table (z up) at (x, y) turned by `yaw`.
Pose upright(double x, double y, double z, double yaw);

// `n` boxes standing on the table on a grid of 4 columns (cell 0.15 x 0.13 m), sides
// 7-11 x 5-9 cm, height 4-10 cm, yaw within +-0.6 rad; names box0, box1, ...
std::vector<TexturedBox> grid_boxes(int n, std::uint64_t seed);

// Writes object.json and the six face_*.png of `box` into dir/box.name.
void write_object_folder(const std::filesystem::path& dir, const TexturedBox& box);

}  // namespace ksmc::tools::stereo_synth
