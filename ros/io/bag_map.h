// The last nav_msgs/OccupancyGrid of a rosbag (for `indoor --bag FILE.bag`, and the
// ksmc-bag2map tool), and writing maps into a bag (tests, examples).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nav_msgs/OccupancyGrid.h>

namespace ksmc::ros_io {

// Throws std::runtime_error naming the bag when it cannot be read or has no message of
// type nav_msgs/OccupancyGrid on `topic`.
nav_msgs::OccupancyGrid read_last_map(const std::filesystem::path& bag, const std::string& topic = "/map");

// Writes the maps on `topic`, one second apart from their header stamps (or t = 1, 2, ...).
void write_map_bag(const std::filesystem::path& bag, const std::vector<nav_msgs::OccupancyGrid>& maps,
                   const std::string& topic = "/map");

}  // namespace ksmc::ros_io
