// run_domain_main with a node's settings (C++20 side of domain_run.h). `inputs` are the
// arguments before --out: the positional input, or flags that replace it (--cloud ...).
#pragma once

#include "ros/src/domain_run.h"
#include "runtime/cli/domain_spec.h"

namespace ksmc::ros_nodes {

RunOutcome run_spec(const runtime::cli::DomainSpec& spec, const std::vector<std::string>& inputs,
                    const std::filesystem::path& out_dir, const RunSettings& settings);

}  // namespace ksmc::ros_nodes
