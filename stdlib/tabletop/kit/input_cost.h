// What a table-top run on a large input costs, estimated from its size before the
// expensive work (issue 16; runtime/cli/work_estimate.h prints the line and applies
// --max-memory-mb): a point cloud by its points (the perception front end), a scene by
// its objects (the relations and the initial Markov logic inference grow with the pairs
// of objects). The constants and how they were measured are in input_cost.cpp.
#pragma once

#include <cstddef>
#include <string>

#include "runtime/cli/work_estimate.h"

namespace ksmc::runtime::cli {
struct DomainInput;
}

namespace ksmc::stdlib::tabletop::kit {

runtime::cli::WorkEstimate cloud_estimate(const std::string& file, std::size_t points, const runtime::cli::DomainInput& in);
runtime::cli::WorkEstimate scene_estimate(const std::string& file, std::size_t objects, const runtime::cli::DomainInput& in);

}  // namespace ksmc::stdlib::tabletop::kit
