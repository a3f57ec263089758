// nav_msgs/OccupancyGrid <-> map_server files (PGM image + YAML), the form the indoor
// domain reads. Trinary, as map_server writes maps: occupancy >= occupied_thresh * 100 ->
// black (0), <= free_thresh * 100 -> white (254), else and unknown (-1) -> grey (205).
// Grid row 0 is the bottom row (y = origin); image row 0 is the top: rows are flipped.
#pragma once

#include <filesystem>
#include <string>

#include <nav_msgs/OccupancyGrid.h>

namespace ksmc::ros_io {

struct GridThresholds {
  double occupied = 0.65;
  double free = 0.196;
};

// Writes DIR/STEM.pgm and DIR/STEM.yaml; returns the YAML's path. Throws
// std::runtime_error naming the file on failure or an inconsistent grid.
std::filesystem::path write_map_files(const nav_msgs::OccupancyGrid& grid, const std::filesystem::path& dir,
                                      const std::string& stem, const GridThresholds& thresholds = {});

// Reads a map_server YAML (image, resolution, origin, negate, occupied_thresh, free_thresh)
// and its image into a grid (0 free, 100 occupied, -1 unknown). Errors name the file.
nav_msgs::OccupancyGrid read_map_files(const std::filesystem::path& yaml);

// The yaw of a (planar) quaternion.
double yaw_of(const geometry_msgs::Quaternion& q);

}  // namespace ksmc::ros_io
