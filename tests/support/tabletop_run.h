// Running the `tabletop` domain binary from a test (KSMC_TABLETOP_EXE, set by the test's
// CMakeLists) and reading back the JSON files it wrote.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace ksmc::tests {

#ifdef KSMC_TABLETOP_EXE
// Runs `tabletop <args>` through the shell with stdout and stderr in `log`; returns the status
// std::system gives (0 when the binary exited 0).
inline int run_tabletop(const std::string& args, const std::filesystem::path& log) {
  const std::string cmd = std::string(KSMC_TABLETOP_EXE) + " " + args + " > " + log.string() + " 2>&1";
  return std::system(cmd.c_str());
}
#endif

inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

}  // namespace ksmc::tests
