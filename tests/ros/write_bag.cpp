// ros_write_bag MAP.yaml OUT.bag: a map_server map as one nav_msgs/OccupancyGrid on /map in a
// new bag (the `indoor --bag` test's input).
#include <exception>
#include <iostream>

#include "ros/io/bag_files.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: ros_write_bag MAP.yaml OUT.bag\n";
    return 2;
  }
  try {
    ksmc::ros_io::map_files_to_bag(argv[1], argv[2]);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "ros_write_bag: " << e.what() << "\n";
    return 1;
  }
}
