// Bags <-> map_server files with standard library types only, so C++20 code (the indoor
// kit's `--bag FILE.bag` flag, which cannot include ROS 1 message headers) can call them.
// The hook in stdlib/indoor/kit/kit.cpp load() (see docs/ros.md):
//   std::filesystem::path path = in.inputs.at(0);
//   if (in.flags.given("bag"))
//     path = ksmc::ros_io::extract_last_map(in.flags.text("bag"), in.out_dir / "bag_map");
#pragma once

#include <filesystem>
#include <string>

namespace ksmc::ros_io {

// The last nav_msgs/OccupancyGrid on `topic` of `bag` as DIR/map.pgm + DIR/map.yaml (DIR is
// created); returns the YAML's path. Throws std::runtime_error naming the bag or file.
std::filesystem::path extract_last_map(const std::filesystem::path& bag, const std::filesystem::path& dir,
                                       const std::string& topic = "/map");

// A map_server map (YAML + image) written as one nav_msgs/OccupancyGrid on `topic` into a
// new bag (examples, tests).
void map_files_to_bag(const std::filesystem::path& yaml, const std::filesystem::path& bag, const std::string& topic = "/map");

}  // namespace ksmc::ros_io
