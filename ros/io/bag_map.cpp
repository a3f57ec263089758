#include "ros/io/bag_map.h"

#include <optional>
#include <stdexcept>

#include <rosbag/bag.h>
#include <rosbag/view.h>

namespace ksmc::ros_io {

nav_msgs::OccupancyGrid read_last_map(const std::filesystem::path& path, const std::string& topic) {
  std::optional<nav_msgs::OccupancyGrid> last;
  try {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Read);
    rosbag::View view(bag, rosbag::TopicQuery(topic));
    for (const rosbag::MessageInstance& m : view) {  // in time order
      if (auto grid = m.instantiate<nav_msgs::OccupancyGrid>()) last = *grid;
    }
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
  if (!last) throw std::runtime_error(path.string() + ": no nav_msgs/OccupancyGrid on " + topic);
  return *last;
}

void write_map_bag(const std::filesystem::path& path, const std::vector<nav_msgs::OccupancyGrid>& maps,
                   const std::string& topic) {
  try {
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    for (std::size_t i = 0; i < maps.size(); ++i) {
      const ros::Time t = maps[i].header.stamp.isZero() ? ros::Time(static_cast<double>(i + 1)) : maps[i].header.stamp;
      bag.write(topic, t, maps[i]);
    }
    bag.close();
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace ksmc::ros_io
