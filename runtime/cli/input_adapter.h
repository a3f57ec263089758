// Input adapters: flags that turn another kind of input into the domain's input file before
// `load` runs, e.g. `--bag FILE.bag` (the last /map of a rosbag as a map_server map), added by
// ros/ when the ROS packages are present. An adapter registers itself from a static object in
// a source file of the binary (`KSMC_REGISTER_INPUT_ADAPTER`); run_domain_main() offers its
// flag on every domain binary it is linked into and, when the flag is given, appends the file
// the adapter writes (into a scratch folder removed after the run) to the positional inputs.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace ksmc::runtime::cli {

struct InputAdapter {
  std::string flag;  // long name without dashes: "bag"
  std::string help;
  std::string value_name = "FILE";
  // Writes the domain input for `value` into `scratch` (an empty folder) and returns its path;
  // throws std::exception naming the file on bad input.
  std::function<std::filesystem::path(const std::string& value, const std::filesystem::path& scratch)> to_input;
};

// Registered adapters, in registration order.
std::vector<InputAdapter>& input_adapters();

struct InputAdapterRegistration {
  explicit InputAdapterRegistration(InputAdapter a) { input_adapters().push_back(std::move(a)); }
};

}  // namespace ksmc::runtime::cli
