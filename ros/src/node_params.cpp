#include "ros/src/node_params.h"

#include <ros/console.h>

namespace ksmc::ros_nodes {

bool read_node_params(const ros::NodeHandle& pnh, int default_iterations, NodeParams& out) {
  int iterations = default_iterations, seed = 1, chains = 1;
  std::string extra;
  pnh.param("iterations", iterations, iterations);
  pnh.param("seed", seed, seed);
  pnh.param("chains", chains, chains);
  pnh.param("extra_args", extra, std::string());
  pnh.param("output_root", out.output_root, std::string());
  if (iterations < 0 || chains <= 0 || seed < 0) {
    ROS_FATAL("ksmc: bad parameters: need ~iterations >= 0 (0: until the plateau), ~chains > 0, ~seed >= 0");
    return false;
  }
  out.run.iterations = iterations;
  out.run.seed = seed;
  out.run.chains = chains;
  out.run.extra_args = split_args(extra);
  return true;
}

}  // namespace ksmc::ros_nodes
