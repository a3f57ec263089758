// The indoor domain's spec from its generated binding (docs/binding.md) and kit: the only
// place the indoor node names the kit's spec function.
#include "indoor_model.h"
#include "ros/src/run_spec.h"
#include "stdlib/indoor/kit/kit.h"

namespace ksmc::ros_nodes {

RunOutcome run_indoor(const std::filesystem::path& input, const std::filesystem::path& out_dir, const RunSettings& settings) {
  static const runtime::cli::DomainSpec spec =
      stdlib::indoor::kit::domain_spec(ksmc_generated::indoor::binding());
  return run_spec(spec, {input.string()}, out_dir, settings);
}

}  // namespace ksmc::ros_nodes
