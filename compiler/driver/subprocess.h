// Running the build tools of `ksmc build`: PATH lookup and a child process whose output
// goes to a log file or to our stderr.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ksmc::compiler::driver {

// The first executable `name` on PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

struct ProcessResult {
  bool started = false;  // false: could not run it (`error` says why)
  int exit_code = -1;    // exit status, or 128 + signal when killed
  std::string error;
};

inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT

// Runs argv[0] (a path) with argv, waits for it. Its stdout and stderr are appended to
// `log` when given, else both go to this process's stderr. While it runs, SIGINT, SIGTERM
// and SIGHUP only stop the child (exit_code 128 + signal) and are recorded
// (runtime::io::cancel_requested()), so the caller can clean up.
ProcessResult run_process(const std::vector<std::string>& argv, const std::optional<std::filesystem::path>& log);

}  // namespace ksmc::compiler::driver
