// ros_tabletop_check SCENE.json OUT_ROOT TIMEOUT_S [--cloud]: the client side of the
// table-top node test. Publishes the scene JSON latched on /ksmc_tabletop/scene, waits for
// the node's scene graph and markers and checks them against the scene and the node's output
// folder (OUT_ROOT/scene_1/scene_graph.json). With --cloud it then publishes a synthetic
// PointCloud2 (a table and two boxes, some NaN points) on /points and checks the second run
// (OUT_ROOT/scene_2): two objects on the table, one box marker each in the cloud's frame.
// One PASS / FAIL line per assertion.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "ros/io/cloud_files.h"
#include "tests/ros/check_support.h"

using ksmc_ros_test::check;

#ifdef KSMC_ROS_TEST_CLOUD  // built with the point-cloud front end (tests/ros/CMakeLists.txt)
#include "tests/ros/scene_cloud.h"

namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return in ? nlohmann::json::parse(in) : nlohmann::json();
}

// Each true box has a found box whose sides (sorted) are within 1 cm of its own.
bool sizes_found(const std::vector<std::array<double, 3>>& truth, const nlohmann::json& objects) {
  for (auto t : truth) {
    std::sort(t.begin(), t.end());
    bool found = false;
    for (const auto& o : objects) {
      std::array<double, 3> s = {o["size"][0], o["size"][1], o["size"][2]};
      std::sort(s.begin(), s.end());
      found = found || (std::abs(s[0] - t[0]) < 0.01 && std::abs(s[1] - t[1]) < 0.01 && std::abs(s[2] - t[2]) < 0.01);
    }
    if (!found) return false;
  }
  return true;
}

// The cloud case: the node's second run (OUT_ROOT/scene_2) on the synthetic cloud.
void check_cloud_run(const std::string& graph_text, const visualization_msgs::MarkerArray& markers,
                     const std::string& out_root, const std::string& frame, const std::vector<std::array<double, 3>>& truth) {
  const auto g = nlohmann::json::parse(graph_text);
  const std::size_t n = g["objects"].size(), want = truth.size();
  check(n == want, "cloud: scene_graph: " + std::to_string(n) + " objects (" + std::to_string(want) + " boxes in the cloud)");
  std::size_t on_table = 0, flagged = 0;
  for (const auto& s : g["support"]) on_table += s[1] == "table" ? 1 : 0;
  for (const auto& o : g["objects"]) flagged += o["false"] == true || o["hidden"] == true ? 1 : 0;
  check(on_table == want && g["support"].size() == want,
        "cloud: " + std::to_string(on_table) + " objects supported by the table, " + std::to_string(g["support"].size()) +
            " support edges");
  check(flagged == 0, "cloud: no object decided false or hidden");
  check(read_json(out_root + "/scene_2/scene_graph.json") == g, "cloud: the published scene graph is the node's scene_graph.json");
  const auto scene = read_json(out_root + "/scene_2/scene.json");  // the boxes the front end found
  check(scene.is_object() && scene["objects"].size() == n, "cloud: the run's scene.json holds the " + std::to_string(n) + " boxes found");
  check(scene.is_object() && sizes_found(truth, scene["objects"]), "cloud: every box of the cloud found with its sides within 1 cm");
  check(markers.markers.size() == 1 + n, "cloud: markers: " + std::to_string(markers.markers.size()) + " = 1 DELETEALL + " +
                                             std::to_string(n) + " boxes");
  bool boxes = markers.markers.size() == 1 + n && scene.is_object();
  for (std::size_t i = 0; boxes && i < n; ++i) {
    const auto& m = markers.markers[i + 1];
    const auto& s = scene["objects"][i]["size"];
    boxes = m.type == visualization_msgs::Marker::CUBE && m.header.frame_id == frame && m.scale.x == s[0].get<double>() &&
            m.scale.y == s[1].get<double>() && m.scale.z == s[2].get<double>() && m.scale.z > 0.05;
  }
  check(boxes, "cloud: each box marker is a CUBE in the cloud's frame '" + frame + "' with the found box's size");
}

// Publishes the synthetic cloud (with NaN points, as a depth sensor's missing returns) on
// /points and checks the node's second run.
void cloud_case(ros::NodeHandle& nh, std::optional<std::string>& graph, std::optional<visualization_msgs::MarkerArray>& markers,
                const std::string& out_root, double timeout) {
  const auto synthetic = ksmc_ros_test::table_with_two_boxes();
  auto points = synthetic.points;
  const std::size_t finite = points.size();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < 5; ++i) points.insert(points.begin() + static_cast<long>(i * 500), {nan, 0.1F, nan});
  const std::string frame = "test_depth_optical";
  graph.reset();
  markers.reset();
  ros::Publisher pub = nh.advertise<sensor_msgs::PointCloud2>("/points", 1, true);
  pub.publish(ksmc::ros_io::xyz_cloud(points, frame));
  std::cout << "published a PointCloud2 of " << points.size() << " points (" << finite << " finite) on /points" << std::endl;
  ksmc_ros_test::spin_until([&] { return graph && markers; }, timeout);
  check(graph && markers, "cloud: scene_graph and markers received");
  if (graph && markers) check_cloud_run(*graph, *markers, out_root, frame, synthetic.box_sizes);
}

}  // namespace
#endif

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_tabletop_check");
  if (argc < 4 || (argc == 5 && std::string(argv[4]) != "--cloud") || argc > 5) {
    std::cerr << "usage: ros_tabletop_check SCENE.json OUT_ROOT TIMEOUT_S [--cloud]\n";
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
  if (argc == 5) {
#ifdef KSMC_ROS_TEST_CLOUD
    cloud_case(nh, graph, markers, out_root, timeout);
#else
    check(false, "--cloud: this check was built without the point-cloud front end");
#endif
  }
  return ksmc_ros_test::finish();
}
