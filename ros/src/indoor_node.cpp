// ksmc_indoor_node: runs the indoor domain on each new map.
//
// Subscribes  /map (nav_msgs/OccupancyGrid, latched by map_server / SLAM)
// Publishes   (latched, private)
//   ~markers            visualization_msgs/MarkerArray: unit outlines by type, doors, labels
//   ~segmentation       nav_msgs/OccupancyGrid: cell = unit id % 100, -1 = no unit
//   ~segmentation_ids   std_msgs/String: JSON side table of the segmentation's ids
//   ~scene_graph        std_msgs/String: JSON units / doors / adjacency in metres
// Parameters (private): ~iterations (5000; 0 = until the plateau, --iterations auto), ~seed (1), ~chains (1), ~occupied_thresh (0.65),
//   ~free_thresh (0.196), ~extra_args ("", further indoor flags), ~output_root ("": a temp
//   folder per map, removed after publishing; else <root>/map_<n> is kept, report.html included).
// Maps arriving during a run are not queued: the newest one is run next.
#include <filesystem>
#include <optional>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "ros/io/grid_files.h"
#include "ros/io/indoor_messages.h"
#include "ros/src/domain_run.h"
#include "ros/src/node_params.h"

namespace {

namespace rn = ksmc::ros_nodes;
namespace ri = ksmc::ros_io;

struct Publishers {
  ros::Publisher markers, segmentation, ids, graph;
};

void process(const nav_msgs::OccupancyGrid& map, const rn::RunSettings& run,
             const ri::GridThresholds& th, const std::string& output_root, unsigned count, const Publishers& pub) {
  const std::filesystem::path work = rn::fresh_folder("ksmc-indoor-node");
  const std::filesystem::path out = output_root.empty() ? work / "out" : std::filesystem::path(output_root) / ("map_" + std::to_string(count));
  try {
    const auto yaml = ri::write_map_files(map, work, "map", th);
    const std::string length = run.iterations == 0 ? "until the plateau" : std::to_string(run.iterations) + " iterations";
    ROS_INFO("ksmc: map %u (%ux%u, %.3f m/cell): running indoor, %s", count, map.info.width, map.info.height,
             static_cast<double>(map.info.resolution), length.c_str());
    const rn::RunOutcome r = rn::run_indoor(yaml, out, run);
    if (rn::interrupted(r.exit_code)) {
      ROS_WARN("ksmc: map %u: run interrupted (exit %d)%s%s; shutting down", count, r.exit_code,
               output_root.empty() ? "" : ", outputs of the best state so far in ", output_root.empty() ? "" : out.c_str());
      ros::shutdown();
    } else if (r.exit_code != 0) {
      ROS_ERROR("ksmc: indoor run failed (exit %d): %s", r.exit_code, r.messages.c_str());
    } else {
      const ri::IndoorMessages m = ri::indoor_messages(out, map);
      pub.markers.publish(m.markers);
      pub.segmentation.publish(m.segmentation);
      std_msgs::String ids, graph;
      ids.data = m.id_table;
      graph.data = m.scene_graph;
      pub.ids.publish(ids);
      pub.graph.publish(graph);
      ROS_INFO("ksmc: map %u: %zu units, %zu doors, %zu markers published%s%s", count, m.units, m.doors,
               m.markers.markers.size(), output_root.empty() ? "" : "; report: ",
               output_root.empty() ? "" : (out / "report.html").c_str());
    }
  } catch (const std::exception& e) {
    ROS_ERROR("ksmc: map %u: %s", count, e.what());
  }
  std::error_code ec;
  std::filesystem::remove_all(work, ec);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "ksmc_indoor_node");
  ros::NodeHandle nh, pnh("~");
  rn::NodeParams params;
  if (!rn::read_node_params(pnh, 5000, params)) return 2;
  const rn::RunSettings& run = params.run;
  const std::string& output_root = params.output_root;
  ri::GridThresholds th;
  pnh.param("occupied_thresh", th.occupied, th.occupied);
  pnh.param("free_thresh", th.free, th.free);
  if (!(th.free >= 0.0 && th.free < th.occupied && th.occupied <= 1.0)) {
    ROS_FATAL("ksmc: bad parameters: need 0 <= ~free_thresh < ~occupied_thresh <= 1");
    return 2;
  }

  Publishers pub;
  pub.markers = pnh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  pub.segmentation = pnh.advertise<nav_msgs::OccupancyGrid>("segmentation", 1, true);
  pub.ids = pnh.advertise<std_msgs::String>("segmentation_ids", 1, true);
  pub.graph = pnh.advertise<std_msgs::String>("scene_graph", 1, true);
  std::optional<nav_msgs::OccupancyGrid> pending;
  const ros::Subscriber sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "map", 1, [&pending](const nav_msgs::OccupancyGrid::ConstPtr& m) { pending = *m; });
  ROS_INFO("ksmc_indoor_node: waiting for %s", sub.getTopic().c_str());
  unsigned count = 0;
  ros::Rate idle(20);
  while (ros::ok()) {
    ros::spinOnce();
    if (pending) {
      const nav_msgs::OccupancyGrid map = std::move(*pending);
      pending.reset();
      process(map, run, th, output_root, ++count, pub);
    }
    idle.sleep();
  }
  return 0;
}
