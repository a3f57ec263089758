// sensor_msgs/PointCloud2 -> a PCD file the point-cloud front end reads (`tabletop --cloud`,
// docs/perception.md), and xyz points -> PointCloud2 (tests, tools).
// Only the float32 fields x, y, z are kept; points with a NaN / infinite coordinate (no
// return, as in organized depth clouds) are skipped. Coordinates are written unchanged
// (ROS clouds are in metres: the node passes --cloud-units from ~cloud_units, default m).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <sensor_msgs/PointCloud2.h>

namespace ksmc::ros_io {

// The finite x, y, z of every point, row by row. Throws std::runtime_error when a field
// x / y / z is missing or not FLOAT32, the cloud is big-endian, or the data is shorter
// than height * row_step / the points overrun a row.
std::vector<std::array<float, 3>> cloud_points(const sensor_msgs::PointCloud2& cloud);

// Writes `points` as a binary PCD (v0.7, fields x y z, F 4) to `path`. Throws
// std::runtime_error naming the file when it cannot be written or `points` is empty.
void write_pcd(const std::filesystem::path& path, const std::vector<std::array<float, 3>>& points);

// An unorganized cloud (height 1) with the fields x, y, z (float32, point_step 16 as
// PCL's PointXYZ) in `frame`.
sensor_msgs::PointCloud2 xyz_cloud(const std::vector<std::array<float, 3>>& points, const std::string& frame);

}  // namespace ksmc::ros_io
