// The private parameters every ksmc node reads: ~iterations, ~seed, ~chains, ~extra_args,
// ~output_root. Returns false (after ROS_FATAL) when they are out of range.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ros/src/domain_run.h"

namespace ksmc::ros_nodes {

struct NodeParams {
  RunSettings run;
  std::string output_root;  // "" = a temp folder per input, removed after publishing
};

bool read_node_params(const ros::NodeHandle& private_nh, int default_iterations, NodeParams& out);

}  // namespace ksmc::ros_nodes
