// Ground truth of a generated floor plan in world.json form, shared by the simulated office
// (sim_floor_plan) and the plan family (plan_family): the map header of the rendered image, an
// axis-aligned unit from its wall centre lines, a door segment along a wall.
#pragma once

#include <array>
#include <string>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::tools::indoor_sim {

// The map header of `image` (map_saver grey values) at `resolution`: size and class counts.
stdlib::indoor::io::MapInfo truth_map_info(const cv::Mat1b& image, double resolution, const std::string& source);

// A unit of probability 1 for `type`, the rectangle x0..x1 x y0..y1 (cells).
stdlib::indoor::io::UnitResult axis_unit(int id, const std::string& type, int x0, int y0, int x1, int y1);

// The segment of a door `width` cells long starting at `from`, on a horizontal (row `at`) or
// vertical (column `at`) wall.
std::array<stdlib::indoor::Point2, 2> axis_door_segment(bool horizontal, int at, int from, int width);

}  // namespace ksmc::tools::indoor_sim
