// ksmc_tabletop_node: runs the table-top domain on each scene (until the point-cloud front
// end exists, a scene is the JSON of examples/tabletop/*.json on a std_msgs/String topic).
//
// Subscribes  ~scene (std_msgs/String, scene JSON; an "image" path in it must be absolute)
// Publishes   (latched, private)
//   ~scene_graph  std_msgs/String: scene_graph.json (objects with P(false) / P(hidden),
//                 support and contact edges)
//   ~markers      visualization_msgs/MarkerArray: one box per object in ~frame_id (camera
//                 frame), red = false estimate, orange = hidden supporter, green = fine
// Parameters (private): ~iterations (2000), ~seed (1), ~chains (1), ~extra_args (""),
//   ~frame_id ("camera"), ~output_root ("" = temp folder per scene, removed; else kept).
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

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

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_tabletop_node");
  ros::NodeHandle pnh("~");
  rn::NodeParams params;
  if (!rn::read_node_params(pnh, 2000, params)) return 2;
  const rn::RunSettings& run = params.run;
  const std::string& output_root = params.output_root;
  std::string frame;
  pnh.param("frame_id", frame, std::string("camera"));
  ros::Publisher graph_pub = pnh.advertise<std_msgs::String>("scene_graph", 1, true);
  ros::Publisher marker_pub = pnh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  std::optional<std::string> pending;
  const ros::Subscriber sub =
      pnh.subscribe<std_msgs::String>("scene", 1, [&pending](const std_msgs::String::ConstPtr& m) { pending = m->data; });
  ROS_INFO("ksmc_tabletop_node: waiting for %s", sub.getTopic().c_str());
  unsigned count = 0;
  ros::Rate idle(20);
  while (ros::ok()) {
    ros::spinOnce();
    if (pending) {
      const std::string text = std::move(*pending);
      pending.reset();
      ++count;
      const auto work = rn::fresh_folder("ksmc-tabletop-node");
      const auto out = output_root.empty() ? work / "out" : std::filesystem::path(output_root) / ("scene_" + std::to_string(count));
      try {
        const nlohmann::json scene = nlohmann::json::parse(text);
        std::ofstream(work / "scene.json") << text;
        const rn::RunOutcome r = rn::run_tabletop(work / "scene.json", out, run);
        if (r.exit_code == rn::kExitInterrupted) {
          ros::shutdown();
        } else if (r.exit_code != 0) {
          ROS_ERROR("ksmc: table-top run failed (exit %d): %s", r.exit_code, r.messages.c_str());
        } else {
          std::ifstream in(out / "scene_graph.json");
          const nlohmann::json graph = nlohmann::json::parse(in);
          std_msgs::String msg;
          msg.data = graph.dump();
          graph_pub.publish(msg);
          marker_pub.publish(boxes(scene, graph, frame));
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
