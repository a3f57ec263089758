// In-process domain runs for the nodes: run_domain_main (runtime/cli) on one input into an
// output folder, argv built from the node's parameters, no progress display.
// Standard library types only: the nodes are C++17 (ROS 1 message headers do not compile as
// C++20) and include this header, the implementation is C++20.
#pragma once

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

namespace ksmc::ros_nodes {

inline constexpr int kExitInterrupted = 130;  // runtime::cli::kExitInterrupted (Ctrl-C)

// A run stopped by SIGINT, SIGTERM (roslaunch's stop, Slurm) or SIGHUP exits 128 + signal
// after writing the complete outputs of its best state, marked "interrupted"; the node then
// shuts down instead of waiting for the next input.
inline bool interrupted(int exit_code) {
  return exit_code == 128 + SIGINT || exit_code == 128 + SIGTERM || exit_code == 128 + SIGHUP;
}

struct RunSettings {
  long long iterations = 5000;  // 0 = --iterations auto (until the plateau)
  long long seed = 1;
  int chains = 1;
  std::vector<std::string> extra_args;  // further domain flags, e.g. {"--source-refresh", "100"}
};

struct RunOutcome {
  int exit_code = 0;
  std::string messages;  // the run's stderr text (errors, warnings)
};

// indoor_run.cpp / tabletop_run.cpp: the domains built from domains/<domain>.ksm.
RunOutcome run_indoor(const std::filesystem::path& input, const std::filesystem::path& out_dir, const RunSettings& settings);
RunOutcome run_tabletop(const std::filesystem::path& input, const std::filesystem::path& out_dir, const RunSettings& settings);
// `tabletop --cloud CLOUD --cloud-units UNITS` (docs/perception.md): the point-cloud front end
// finds the table and boxes (written to OUT/scene.json), then the same inference runs.
RunOutcome run_tabletop_cloud(const std::filesystem::path& cloud, const std::string& units,
                              const std::filesystem::path& out_dir, const RunSettings& settings);

// "--a 1 --b" -> {"--a", "1", "--b"} (the ~extra_args parameter).
std::vector<std::string> split_args(const std::string& text);

// A fresh folder under the system temp folder: <tmp>/<prefix>-<pid>-<n>.
std::filesystem::path fresh_folder(const std::string& prefix);

}  // namespace ksmc::ros_nodes
