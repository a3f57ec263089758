// ksmc_map_publisher MAP.yaml [--topic /map] [--frame map]
// Publishes a map_server map (YAML + image) once, latched, as nav_msgs/OccupancyGrid, and
// keeps it available until Ctrl-C: a stand-in for map_server (not packaged in Debian).
#include <cstring>
#include <iostream>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include "ros/io/grid_files.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_map_publisher");
  std::string yaml, topic = "/map", frame = "map";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--topic" || a == "--frame") && i + 1 < argc) (a == "--topic" ? topic : frame) = argv[++i];
    else if (!a.empty() && a[0] != '-' && yaml.empty()) yaml = a;
    else {
      std::cerr << "usage: ksmc_map_publisher MAP.yaml [--topic /map] [--frame map]\n";
      return 2;
    }
  }
  if (yaml.empty()) {
    std::cerr << "usage: ksmc_map_publisher MAP.yaml [--topic /map] [--frame map]\n";
    return 2;
  }
  nav_msgs::OccupancyGrid grid;
  try {
    grid = ksmc::ros_io::read_map_files(yaml);
  } catch (const std::exception& e) {
    std::cerr << "ksmc_map_publisher: error: " << e.what() << '\n';
    return 1;
  }
  ros::NodeHandle nh;
  grid.header.frame_id = frame;
  grid.header.stamp = ros::Time::now();
  grid.info.map_load_time = grid.header.stamp;
  ros::Publisher pub = nh.advertise<nav_msgs::OccupancyGrid>(topic, 1, true);
  pub.publish(grid);
  ROS_INFO("ksmc_map_publisher: %s (%ux%u) on %s", yaml.c_str(), grid.info.width, grid.info.height, pub.getTopic().c_str());
  ros::spin();
  return 0;
}
