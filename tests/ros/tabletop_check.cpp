// ros_tabletop_check SCENE.json OUT_ROOT TIMEOUT_S: the client side of the table-top node
// test. Publishes the scene JSON latched on /ksmc_tabletop/scene, waits for the node's
// scene graph and markers and checks them against the scene and the node's output folder
// (OUT_ROOT/scene_1/scene_graph.json). One PASS / FAIL line per assertion.
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "tests/ros/check_support.h"

using ksmc_ros_test::check;

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_tabletop_check");
  if (argc < 4) {
    std::cerr << "usage: ros_tabletop_check SCENE.json OUT_ROOT TIMEOUT_S\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  const auto scene = nlohmann::json::parse(text.str());
  const std::string out_root = argv[2];
  const double timeout = std::stod(argv[3]);
  ros::NodeHandle nh;
  std::optional<std::string> graph;
  std::optional<visualization_msgs::MarkerArray> markers;
  auto s1 = nh.subscribe<std_msgs::String>("/ksmc_tabletop/scene_graph", 1,
                                           [&](const std_msgs::String::ConstPtr& m) { graph = m->data; });
  auto s2 = nh.subscribe<visualization_msgs::MarkerArray>(
      "/ksmc_tabletop/markers", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) { markers = *m; });
  ros::Publisher pub = nh.advertise<std_msgs::String>("/ksmc_tabletop/scene", 1, true);
  std_msgs::String msg;
  msg.data = text.str();
  pub.publish(msg);
  std::cout << "published " << argv[1] << " on /ksmc_tabletop/scene, waiting up to " << timeout << " s" << std::endl;
  ksmc_ros_test::spin_until([&] { return graph && markers; }, timeout);
  check(graph && markers, "scene_graph and markers received");
  if (!(graph && markers)) return 1;
  const auto g = nlohmann::json::parse(*graph);
  const std::size_t n = scene["objects"].size();
  check(g["objects"].size() == n, "scene_graph: " + std::to_string(g["objects"].size()) + " objects (scene: " + std::to_string(n) + ")");
  std::ifstream file(out_root + "/scene_1/scene_graph.json");
  check(file && nlohmann::json::parse(file) == g, "the published scene graph is the node's scene_graph.json");
  check(markers->markers.size() == 1 + n, "markers: " + std::to_string(markers->markers.size()) + " = 1 DELETEALL + " +
                                              std::to_string(n) + " boxes");
  bool sizes = true;
  for (std::size_t i = 0; i < n && i + 1 < markers->markers.size(); ++i) {
    const auto& m = markers->markers[i + 1];
    const auto& s = scene["objects"][i]["size"];
    sizes = sizes && m.type == visualization_msgs::Marker::CUBE && m.scale.x == s[0].get<double>() &&
            m.scale.y == s[1].get<double>() && m.scale.z == s[2].get<double>() && m.header.frame_id == "camera";
  }
  check(sizes, "each box marker is a CUBE in frame 'camera' with the object's size");
  std::size_t decided_false = 0;
  for (const auto& o : g["objects"]) decided_false += o["false"] == true ? 1 : 0;
  check(!g["support"].empty(), "scene_graph: " + std::to_string(g["support"].size()) + " support edges, " +
                                   std::to_string(decided_false) + " object(s) decided false");
  return ksmc_ros_test::finish();
}
