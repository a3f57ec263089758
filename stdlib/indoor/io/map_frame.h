// Cell coordinates <-> map-frame metres (ROS map_server convention): the origin is the pose of
// the lower-left corner of the image's lower-left pixel, x to the right, y up, rotated by yaw.
// Cell coordinates are the image convention of world_result.h (integer = cell centre, rows
// grow downwards), so the cell (c, r) has its centre at (c + 0.5, rows - r - 0.5) * resolution
// before the origin's rotation and translation. --robot and --path read metres this way, and
// world.json / path.json / world.obj write them this way.
#pragma once

#include <cmath>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

struct MapFrame {
  double resolution = 0.05;
  Pose2 origin;
  int rows = 0;

  Point2 to_metres(Point2 cell) const {
    const double lx = (cell.x + 0.5) * resolution, ly = (rows - 0.5 - cell.y) * resolution;
    const double c = std::cos(origin.yaw), s = std::sin(origin.yaw);
    return {origin.x + c * lx - s * ly, origin.y + s * lx + c * ly};
  }
  Point2 to_cells(Point2 metres) const {
    const double dx = metres.x - origin.x, dy = metres.y - origin.y;
    const double c = std::cos(origin.yaw), s = std::sin(origin.yaw);
    const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
    return {lx / resolution - 0.5, rows - 0.5 - ly / resolution};
  }
};

inline MapFrame frame_of(const MapInfo& m) { return {m.resolution, m.origin, m.height}; }
inline MapFrame frame_of(const OccupancyMap& m) { return {m.resolution, m.origin, m.rows()}; }

}  // namespace ksmc::stdlib::indoor::io
