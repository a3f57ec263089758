// Simulated depth sensor: one ray per pixel (every `stride`-th pixel) from the camera,
// nearest hit among the boxes and the table top (visible surfaces only), Gaussian depth
// noise growing with the square of the depth (structured-light sensors), optional missing
// returns. Points come out in the camera frame (OpenCV axes), metres.
#pragma once

#include <span>
#include <vector>

#include "tools/tabletop_sim/box_geometry.h"
#include "tools/tabletop_sim/camera.h"
#include "tools/tabletop_sim/physics.h"

namespace ksmc::tools::tabletop_sim {

struct DepthParams {
  int stride = 2;               // pixel step in u and v
  double sigma_at_1m = 0.001;   // m; depth noise sigma = sigma_at_1m * z^2 (z in m)
  double missing_rate = 0.0;    // chance that a pixel returns nothing
  double max_depth = 3.0;       // m; farther hits (or none) return nothing
};

// Nearest positive ray parameter at which origin + s * dir enters the box, or a negative value.
double ray_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const Box& box);

std::vector<Eigen::Vector3d> render_depth(Rng& rng, const Camera& camera, const Pose& table_from_camera,
                                          std::span<const Box> boxes, const TableSpec& table, const DepthParams& params);

}  // namespace ksmc::tools::tabletop_sim
