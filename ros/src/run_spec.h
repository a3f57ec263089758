// run_domain_main on one input with a node's settings (C++20 side of domain_run.h).
#pragma once

#include "ros/src/domain_run.h"
#include "runtime/cli/domain_spec.h"

namespace ksmc::ros_nodes {

RunOutcome run_spec(const runtime::cli::DomainSpec& spec, const std::filesystem::path& input,
                    const std::filesystem::path& out_dir, const RunSettings& settings);

}  // namespace ksmc::ros_nodes
