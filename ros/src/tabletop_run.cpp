// The table-top domain's spec from its generated code and kit: the only place the table-top
// node names the kit's spec function.
#include "ros/src/run_spec.h"
#include "stdlib/tabletop/kit/kit.h"
#include "tabletop_model.h"

namespace ksmc::ros_nodes {

RunOutcome run_tabletop(const std::filesystem::path& input, const std::filesystem::path& out_dir, const RunSettings& settings) {
  static const runtime::cli::DomainSpec spec =
      stdlib::tabletop::kit::domain_spec(ksmc_generated::tabletop::binding());
  return run_spec(spec, input, out_dir, settings);
}

}  // namespace ksmc::ros_nodes
