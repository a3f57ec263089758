#include "ros/io/bag_files.h"

#include "ros/io/bag_map.h"
#include "ros/io/grid_files.h"

namespace ksmc::ros_io {

std::filesystem::path extract_last_map(const std::filesystem::path& bag, const std::filesystem::path& dir,
                                       const std::string& topic) {
  return write_map_files(read_last_map(bag, topic), dir, "map");
}

void map_files_to_bag(const std::filesystem::path& yaml, const std::filesystem::path& bag, const std::string& topic) {
  nav_msgs::OccupancyGrid grid = read_map_files(yaml);
  grid.header.stamp = ros::Time(1.0);
  write_map_bag(bag, {grid}, topic);
}

}  // namespace ksmc::ros_io
