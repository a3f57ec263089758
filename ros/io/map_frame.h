// From the indoor outputs' cell coordinates (world.json: x = column, y = row downwards,
// integer = cell centre, in the image written by write_map_files) to metres in the frame of
// the OccupancyGrid the image came from (its info.origin, planar).
#pragma once

#include <cmath>

#include <geometry_msgs/Point.h>
#include <nav_msgs/MapMetaData.h>

#include "ros/io/grid_files.h"

namespace ksmc::ros_io {

class MapFrame {
 public:
  explicit MapFrame(const nav_msgs::MapMetaData& info)
      : res_(info.resolution), height_(info.height), ox_(info.origin.position.x), oy_(info.origin.position.y),
        yaw_(yaw_of(info.origin.orientation)) {}

  geometry_msgs::Point point(double x_img, double y_img, double z = 0.0) const {
    const double gx = (x_img + 0.5) * res_;
    const double gy = (static_cast<double>(height_) - 0.5 - y_img) * res_;
    geometry_msgs::Point p;
    p.x = ox_ + std::cos(yaw_) * gx - std::sin(yaw_) * gy;
    p.y = oy_ + std::sin(yaw_) * gx + std::cos(yaw_) * gy;
    p.z = z;
    return p;
  }
  double metres(double cells) const { return cells * res_; }

 private:
  double res_;
  unsigned height_;
  double ox_, oy_, yaw_;
};

}  // namespace ksmc::ros_io
