// The independent generator's observation of a world (tools/tabletop_indep/world.h): a
// camera, the pose estimates with their own noise model, false estimates of seven kinds,
// keypoints, and the scene / truth JSON the table-top binary and its scorer read.
//
// Its choices differ from tools/tabletop_sim on purpose: no physics engine (stability by
// construction), its own catalogue, pose noise in the camera frame with a heavier tail and a
// larger error along the viewing ray, its own false-estimate kinds and ranges, numeric or
// "obj<k>" ids in shuffled order.
#pragma once

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/tabletop_indep/world.h"

namespace ksmc::tools::tabletop_indep {

enum class FalseKind { none, floating, intersecting, shifted_copy, duplicate, wrong_size, flipped, tilted };
inline constexpr std::array<FalseKind, 7> kFalseKinds{FalseKind::floating,     FalseKind::intersecting,
                                                      FalseKind::shifted_copy, FalseKind::duplicate,
                                                      FalseKind::wrong_size,   FalseKind::flipped,
                                                      FalseKind::tilted};
const char* to_string(FalseKind k);

struct ObserveOptions {
  double false_rate = 0.15;                 // chance per real box of one false estimate
  std::array<double, 7> false_odds{1, 1, 1, 1, 1, 1, 1};  // in kFalseKinds order
  double sigma_t = 0.003;                   // m, lateral pose noise (Student t, 5 dof)
  double depth_factor = 2.0;                // noise along the viewing ray / lateral
  double sigma_r = 1.5;                     // deg per axis
  double min_elevation = 25, max_elevation = 70;  // deg, camera above the table plane
  double min_distance = 0.6, max_distance = 1.3;  // m
  int min_keypoints = 15, max_keypoints = 120;    // per object, log-uniform
  double pixel_sigma = 1.0;
  double outlier_rate = 0.05;
  bool numeric_ids = false;
};

struct Camera {
  double fx = 600, fy = 600, cx = 320, cy = 240;
  int width = 640, height = 480;
  Eigen::Matrix3d rot;  // table from camera (columns: right, down, forward)
  Eigen::Vector3d eye;
};

struct Estimate {
  std::string id;
  int body = -1;  // the world body it estimates, -1 for an extra false box
  FalseKind kind = FalseKind::none;
  Obb clean;      // the pose the estimator found (false pose for a false estimate)
  Obb noisy;      // what the scene file states
  std::vector<Eigen::Vector3d> kp_model;
  std::vector<Eigen::Vector2d> kp_image;
};

struct IndepScene {
  World world;
  Camera camera;
  std::vector<Estimate> estimates;  // output order
  bool numeric_ids = false;         // ids written as JSON numbers
  std::string scene_json() const;
  std::string truth_json() const;   // objects (false, hidden, stable, kind), support, contact
};

// Draws the false estimates, the camera, the noise and keypoints; nullopt when no camera
// placement sees every box.
std::optional<IndepScene> observe(Rng& rng, World world, const ObserveOptions& options);

}  // namespace ksmc::tools::tabletop_indep
