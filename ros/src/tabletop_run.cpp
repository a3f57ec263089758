// The table-top domain's spec from its generated code and kit: the only place the table-top
// node names the kit's spec function.
#include <filesystem>

#include "ros/src/run_spec.h"
#include "runtime/io/atomic_file.h"
#include "stdlib/tabletop/kit/kit.h"
#include "tabletop_model.h"
#ifdef KSMC_ROS_HAVE_PERCEPTION
#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/scene_json.h"
#endif

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
  RunOutcome r = run_spec(tabletop_spec(), {"--cloud", cloud.string(), "--cloud-units", units}, out_dir, settings);
#ifdef KSMC_ROS_HAVE_PERCEPTION
  // The kit writes OUT/scene.json (the boxes found, whose sizes the markers need) through an
  // output folder of its own that is never committed, so the file does not arrive: until
  // the kit writes it with the run's outputs, it is written here from the same
  // deterministic front end (same boxes, byte-identical text).
  if (r.exit_code == 0 && !std::filesystem::exists(out_dir / "scene.json")) {
    namespace pc = stdlib::tabletop::perception;
    pc::CloudOptions options;
    options.units = pc::parse_units(units);
    runtime::io::write_file_atomic(out_dir / "scene.json", pc::scene_json_text(pc::scene_from_cloud(cloud, options).scene));
  }
#endif
  return r;
}

}  // namespace ksmc::ros_nodes
