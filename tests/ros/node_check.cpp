// ros_node_check MAP.yaml OUT_ROOT TIMEOUT_S [BAG]: the client side of the ROS test.
// Publishes the map latched on /map (as a map server would), waits for the outputs of
// ksmc_indoor_node and checks them against the map and the node's output folder
// (OUT_ROOT/map_1/world.json): unit count, marker count, segmentation size and values,
// scene graph. With BAG, first writes the published map into that bag and reads it back.
// Prints one PASS / FAIL line per assertion; exit 0 when all pass.
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "tests/ros/check_support.h"

#include "ros/io/bag_map.h"
#include "ros/io/grid_files.h"

using ksmc_ros_test::check;

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_node_check");
  if (argc < 4) {
    std::cerr << "usage: ros_node_check MAP.yaml OUT_ROOT TIMEOUT_S [BAG]\n";
    return 2;
  }
  nav_msgs::OccupancyGrid map = ksmc::ros_io::read_map_files(argv[1]);
  map.header.frame_id = "map";
  const std::string out_root = argv[2];
  const double timeout = std::stod(argv[3]);
  if (argc > 4) {
    ksmc::ros_io::write_map_bag(argv[4], {map});
    const auto back = ksmc::ros_io::read_last_map(argv[4]);
    check(back.info.width == map.info.width && back.info.height == map.info.height && back.data == map.data,
          "bag " + std::string(argv[4]) + ": the /map written is read back (" + std::to_string(back.info.width) + "x" +
              std::to_string(back.info.height) + ", same cells)");
  }
  ros::NodeHandle nh;
  std::optional<visualization_msgs::MarkerArray> markers;
  std::optional<nav_msgs::OccupancyGrid> seg;
  std::optional<std::string> ids, graph;
  auto s1 = nh.subscribe<visualization_msgs::MarkerArray>("/ksmc_indoor/markers", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) { markers = *m; });
  auto s2 = nh.subscribe<nav_msgs::OccupancyGrid>("/ksmc_indoor/segmentation", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { seg = *m; });
  auto s3 = nh.subscribe<std_msgs::String>("/ksmc_indoor/segmentation_ids", 1, [&](const std_msgs::String::ConstPtr& m) { ids = m->data; });
  auto s4 = nh.subscribe<std_msgs::String>("/ksmc_indoor/scene_graph", 1, [&](const std_msgs::String::ConstPtr& m) { graph = m->data; });
  ros::Publisher pub = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, true);
  map.header.stamp = ros::Time::now();
  pub.publish(map);
  std::cout << "published /map " << map.info.width << "x" << map.info.height << ", waiting up to " << timeout << " s" << std::endl;
  const double secs = ksmc_ros_test::spin_until([&] { return markers && seg && ids && graph; }, timeout);
  check(markers && seg && ids && graph, "all four outputs received (" + std::to_string(static_cast<int>(secs)) + " s)");
  if (!(markers && seg && ids && graph)) return 1;

  std::ifstream world_in(out_root + "/map_1/world.json");
  check(static_cast<bool>(world_in), out_root + "/map_1/world.json written by the node");
  if (!world_in) return 1;
  const auto world = nlohmann::json::parse(world_in);
  const std::size_t units = world["units"].size(), doors = world["doors"].size();
  const auto table = nlohmann::json::parse(*ids);
  check(table["units"].size() == units && units > 0,
        "segmentation_ids: " + std::to_string(table["units"].size()) + " units (world.json: " + std::to_string(units) + ")");
  std::map<std::string, int> per_ns;
  for (const auto& m : markers->markers) ++per_ns[m.action == visualization_msgs::Marker::DELETEALL ? "deleteall" : m.ns];
  check(markers->markers.size() == 1 + 2 * units + doors,
        "markers: " + std::to_string(markers->markers.size()) + " = 1 DELETEALL + " + std::to_string(units) +
            " outlines + " + std::to_string(units) + " labels + " + std::to_string(doors) + " doors");
  check(per_ns["units"] == static_cast<int>(units) && per_ns["labels"] == static_cast<int>(units) &&
            per_ns["doors"] == static_cast<int>(doors),
        "marker namespaces units/labels/doors: " + std::to_string(per_ns["units"]) + "/" + std::to_string(per_ns["labels"]) +
            "/" + std::to_string(per_ns["doors"]));
  bool labelled = true;
  for (const auto& m : markers->markers)
    if (m.ns == "labels") labelled = labelled && m.text.find(' ') != std::string::npos;
  check(labelled, "every label marker reads 'type id'");
  check(seg->info.width == map.info.width && seg->info.height == map.info.height && seg->data.size() == map.data.size(),
        "segmentation " + std::to_string(seg->info.width) + "x" + std::to_string(seg->info.height) + " = map size");
  std::map<int, std::size_t> counts;
  for (const auto v : seg->data) ++counts[v];
  bool values_ok = true;
  std::size_t labelled_cells = 0;
  for (const auto& u : table["units"]) {
    values_ok = values_ok && u["value"] == u["id"].get<int>() % 100;
    labelled_cells += u["cells"].get<std::size_t>();
  }
  check(values_ok && labelled_cells == seg->data.size() - counts[-1] && labelled_cells > 0,
        "segmentation cells: " + std::to_string(labelled_cells) + " in units (value = id % 100), " + std::to_string(counts[-1]) +
            " outside (-1)");
  const auto sg = nlohmann::json::parse(*graph);
  check(sg["units"].size() == units && sg["doors"].size() == doors && sg["adjacent"] == world["adjacent"],
        "scene_graph: " + std::to_string(sg["units"].size()) + " units, " + std::to_string(sg["doors"].size()) + " doors, " +
            std::to_string(sg["adjacent"].size()) + " adjacent pairs");
  bool inside = true;
  const double x1 = map.info.origin.position.x + map.info.width * map.info.resolution;
  const double y1 = map.info.origin.position.y + map.info.height * map.info.resolution;
  for (const auto& u : sg["units"]) {
    const double cx = u["centre"][0], cy = u["centre"][1];
    inside = inside && cx >= map.info.origin.position.x && cx <= x1 && cy >= map.info.origin.position.y && cy <= y1;
  }
  check(inside, "unit centres lie inside the map's extent in metres");
  std::ifstream report(out_root + "/map_1/report.html");
  check(static_cast<bool>(report), out_root + "/map_1/report.html written");
  return ksmc_ros_test::finish();
}
