// ksmc_tabletop_node: runs the table-top domain on each scene: a point cloud (through the
// point-cloud front end, as `tabletop --cloud`) or a scene JSON of examples/tabletop/*.json.
//
// Subscribes  ~cloud_topic (default /points, sensor_msgs/PointCloud2, float32 x y z; points
//             with a NaN coordinate are skipped), written as a PCD and run with --cloud
//             --cloud-units ~cloud_units (default m); the boxes are in the cloud's frame
//             ~scene (std_msgs/String, scene JSON; an "image" path in it must be absolute)
// Publishes   (latched, private)
//   ~scene_graph  std_msgs/String: scene_graph.json (objects with P(false) / P(hidden),
//                 support and contact edges)
//   ~markers      visualization_msgs/MarkerArray: one box per object (in the cloud's frame,
//                 for a scene JSON in ~frame_id, the camera frame), red = false estimate,
//                 orange = hidden supporter, green = fine
// Parameters (private): ~iterations (2000), ~seed (1), ~chains (1), ~extra_args (""),
//   ~frame_id ("camera"), ~cloud_topic ("/points"), ~cloud_units ("m"),
//   ~output_root ("" = temp folder per scene, removed; else kept).
// Inputs that arrive during a run are not queued: the newest (cloud or scene) runs next.
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <variant>

#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "ros/io/cloud_files.h"
#include "ros/src/domain_run.h"
#include "ros/src/node_params.h"

namespace {

namespace rn = ksmc::ros_nodes;

visualization_msgs::MarkerArray boxes(const nlohmann::json& scene, const nlohmann::json& graph, const std::string& frame) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header.frame_id = frame;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  std::map<std::string, nlohmann::json> sizes;
  for (const auto& o : scene.at("objects")) sizes[o.at("id").get<std::string>()] = o.at("size");
  int id = 0;
  for (const auto& o : graph.at("objects")) {
    visualization_msgs::Marker m;
    m.header.frame_id = frame;
    m.header.stamp = ros::Time::now();
    m.ns = "objects";
    m.id = id++;
    m.type = visualization_msgs::Marker::CUBE;
    m.action = visualization_msgs::Marker::ADD;
    const auto& t = o.at("pose").at("t");
    const auto& q = o.at("pose").at("q");  // w, x, y, z
    m.pose.position.x = t[0];
    m.pose.position.y = t[1];
    m.pose.position.z = t[2];
    m.pose.orientation.w = q[0];
    m.pose.orientation.x = q[1];
    m.pose.orientation.y = q[2];
    m.pose.orientation.z = q[3];
    const auto& s = sizes.at(o.at("id").get<std::string>());
    m.scale.x = s[0];
    m.scale.y = s[1];
    m.scale.z = s[2];
    const bool is_false = o.at("false") == true, hidden = o.at("hidden") == true;
    m.color.r = is_false || hidden ? 0.9F : 0.2F;
    m.color.g = is_false ? 0.15F : (hidden ? 0.5F : 0.7F);
    m.color.b = 0.15F;
    m.color.a = 0.6F;
    out.markers.push_back(m);
  }
  return out;
}

// One input: a scene JSON text or a point cloud.
using Input = std::variant<std::string, sensor_msgs::PointCloud2::ConstPtr>;

struct Settings {
  rn::RunSettings run;
  std::string frame, cloud_units;
};

// One run's result: the scene that was run (for the box sizes; a cloud run writes the boxes
// it found to OUT/scene.json) and the frame the boxes are in.
struct Ran {
  int exit_code = 0;
  nlohmann::json scene;
  std::string frame;
};

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": missing after the run");
  return nlohmann::json::parse(in);
}

// Runs one input in `work` into `out`. Throws std::runtime_error on a bad input or a
// failed run (a run stopped by a signal, rn::interrupted, is returned).
Ran run_input(const Input& input, const Settings& s, const std::filesystem::path& work, const std::filesystem::path& out) {
  Ran ran;
  rn::RunOutcome r;
  if (const auto* text = std::get_if<std::string>(&input)) {
    ran.scene = nlohmann::json::parse(*text);
    ran.frame = s.frame;
    std::ofstream(work / "scene.json") << *text;
    r = rn::run_tabletop(work / "scene.json", out, s.run);
  } else {
    const auto& cloud = *std::get<sensor_msgs::PointCloud2::ConstPtr>(input);
    const auto points = ksmc::ros_io::cloud_points(cloud);
    ksmc::ros_io::write_pcd(work / "cloud.pcd", points);
    ROS_INFO("ksmc: cloud %ux%u in '%s': %zu finite points", cloud.width, cloud.height, cloud.header.frame_id.c_str(),
             points.size());
    ran.frame = cloud.header.frame_id.empty() ? s.frame : cloud.header.frame_id;
    r = rn::run_tabletop_cloud(work / "cloud.pcd", s.cloud_units, out, s.run);
  }
  ran.exit_code = r.exit_code;
  if (rn::interrupted(r.exit_code)) return ran;
  if (r.exit_code != 0) throw std::runtime_error("table-top run failed (exit " + std::to_string(r.exit_code) + "): " + r.messages);
  if (ran.scene.is_null()) ran.scene = read_json(out / "scene.json");
  return ran;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_tabletop_node");
  ros::NodeHandle pnh("~");
  rn::NodeParams params;
  if (!rn::read_node_params(pnh, 2000, params)) return 2;
  Settings settings{params.run, "", ""};
  const std::string& output_root = params.output_root;
  std::string cloud_topic;
  pnh.param("frame_id", settings.frame, std::string("camera"));
  pnh.param("cloud_topic", cloud_topic, std::string("/points"));
  pnh.param("cloud_units", settings.cloud_units, std::string("m"));
  ros::Publisher graph_pub = pnh.advertise<std_msgs::String>("scene_graph", 1, true);
  ros::Publisher marker_pub = pnh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  std::optional<Input> pending;
  const ros::Subscriber scene_sub =
      pnh.subscribe<std_msgs::String>("scene", 1, [&pending](const std_msgs::String::ConstPtr& m) { pending = m->data; });
  const ros::Subscriber cloud_sub = pnh.subscribe<sensor_msgs::PointCloud2>(
      cloud_topic, 1, [&pending](const sensor_msgs::PointCloud2::ConstPtr& m) { pending = m; });
  ROS_INFO("ksmc_tabletop_node: waiting for %s and %s", cloud_sub.getTopic().c_str(), scene_sub.getTopic().c_str());
  unsigned count = 0;
  ros::Rate idle(20);
  while (ros::ok()) {
    ros::spinOnce();
    if (pending) {
      const Input input = std::move(*pending);
      pending.reset();
      ++count;
      const auto work = rn::fresh_folder("ksmc-tabletop-node");
      const auto out = output_root.empty() ? work / "out" : std::filesystem::path(output_root) / ("scene_" + std::to_string(count));
      try {
        const Ran ran = run_input(input, settings, work, out);
        if (rn::interrupted(ran.exit_code)) {
          ROS_WARN("ksmc: scene %u: run interrupted (exit %d)%s%s; shutting down", count, ran.exit_code,
                   output_root.empty() ? "" : ", outputs of the best state so far in ", output_root.empty() ? "" : out.c_str());
          ros::shutdown();
        } else {
          const nlohmann::json graph = read_json(out / "scene_graph.json");
          std_msgs::String msg;
          msg.data = graph.dump();
          graph_pub.publish(msg);
          marker_pub.publish(boxes(ran.scene, graph, ran.frame));
          ROS_INFO("ksmc: scene %u: %zu objects, %zu support edges published", count, graph.at("objects").size(),
                   graph.at("support").size());
        }
      } catch (const std::exception& e) {
        ROS_ERROR("ksmc: scene %u: %s", count, e.what());
      }
      std::error_code ec;
      std::filesystem::remove_all(work, ec);
    }
    idle.sleep();
  }
  return 0;
}

