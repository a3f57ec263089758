// A synthetic table-top cloud for the node test: a table plane and two upright boxes (the
// surface grids of tests/tabletop_perception/synthetic_cloud.h) seen from a tilted sensor,
// in metres. Standard types only: the check program that publishes it is C++17 (ROS 1).
#pragma once

#include <array>
#include <vector>

namespace ksmc_ros_test {

struct SceneCloud {
  std::vector<std::array<float, 3>> points;      // sensor frame, metres
  std::vector<std::array<double, 3>> box_sizes;  // the boxes' true sizes (x, y, z), metres
};

SceneCloud table_with_two_boxes();

}  // namespace ksmc_ros_test
