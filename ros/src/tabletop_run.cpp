// The table-top domain's spec from its generated code and kit: the only place the table-top
// node names the kit's spec function.
#include <filesystem>

#include "ros/src/run_spec.h"
#include "stdlib/tabletop/kit/kit.h"
#include "tabletop_model.h"

namespace ksmc::ros_nodes {

namespace {

const runtime::cli::DomainSpec& tabletop_spec() {
  static const runtime::cli::DomainSpec spec =
      stdlib::tabletop::kit::domain_spec(ksmc_generated::tabletop::binding());
  return spec;
}

}  // namespace

RunOutcome run_tabletop(const std::filesystem::path& input, const std::filesystem::path& out_dir, const RunSettings& settings) {
  return run_spec(tabletop_spec(), {input.string()}, out_dir, settings);
}

RunOutcome run_tabletop_cloud(const std::filesystem::path& cloud, const std::string& units,
                              const std::filesystem::path& out_dir, const RunSettings& settings) {
  // The kit writes OUT/scene.json (the boxes found, whose sizes the markers need) with the
  // run's other outputs.
  return run_spec(tabletop_spec(), {"--cloud", cloud.string(), "--cloud-units", units}, out_dir, settings);
}

}  // namespace ksmc::ros_nodes
