// The indoor run's output folder (world.json, labels.png) as ROS messages, in the frame
// of the map it was run on:
//   markers       unit outlines coloured by type (ns "units"), text "type id" (ns "labels"),
//                 doors (ns "doors"); the first marker is DELETEALL (clears the last map's)
//   segmentation  nav_msgs/OccupancyGrid, the map's geometry, cell = unit id % 100, -1 = none
//   id_table      JSON side table of the segmentation's values
//   scene_graph   JSON: units (type, probabilities, centre / size / corners in metres),
//                 doors, adjacency, metrics
#pragma once

#include <filesystem>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <visualization_msgs/MarkerArray.h>

namespace ksmc::ros_io {

struct IndoorMessages {
  visualization_msgs::MarkerArray markers;
  nav_msgs::OccupancyGrid segmentation;
  std::string id_table;
  std::string scene_graph;
  std::size_t units = 0;
  std::size_t doors = 0;
};

// Throws std::runtime_error naming the file when world.json / labels.png is missing or does
// not match the map.
IndoorMessages indoor_messages(const std::filesystem::path& out_dir, const nav_msgs::OccupancyGrid& map);

}  // namespace ksmc::ros_io
