// A deterministic simulated office floor plan, rendered like a gmapping map: rooms, a corridor
// and a hall with wall thickness, doors, furniture, ray-cast exploration from a robot path
// (unexplored space stays unknown, one room is only seen through its door), range noise and
// spurious readings. Used for examples/indoor/sim_office.* and in tests.
#pragma once

#include <cstdint>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::tools::indoor_sim {

using stdlib::indoor::io::WorldResult;

struct SimFloorPlan {
  cv::Mat1b image;    // map_saver grey values: 0 occupied, 205 unknown, 254 free; 600x400 cells
  double resolution;  // m per cell (0.05)
  WorldResult truth;  // the units (wall centre-line rectangles), doors and adjacency
};

SimFloorPlan make_sim_office(std::uint64_t seed = 20130501);

// map_saver-style P5 PGM bytes with a "<resolution> m/pix" comment.
std::string encode_pgm(const cv::Mat1b& image, double resolution);

}  // namespace ksmc::tools::indoor_sim
