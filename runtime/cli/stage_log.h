// Progress of the phases around sampling for large inputs (issue 16): reading and
// preparing the input, a perception front end, model construction, initial inference,
// writing the outputs. The engine's progress line covers sampling; before and after it a
// large run would otherwise sit silent for minutes. Once a kit's work estimate (work_estimate.h)
// reached kStageSeconds or was large enough to be printed, each phase a kit or the driver
// enters prints one stderr line with the seconds since the run started:
//   indoor: 4.1 s: finding wall orientations and unit candidates
// Small runs and --quiet print nothing.
#pragma once

#include <chrono>
#include <ostream>
#include <string>
#include <string_view>

namespace ksmc::runtime::cli {

class StageLog {
 public:
  StageLog(std::string program, std::ostream& err, bool quiet);
  // From now on stages are printed (unless quiet); check_work calls it for large inputs.
  void enable() noexcept { enabled_ = !quiet_; }
  bool enabled() const noexcept { return enabled_; }
  // "<program>: <seconds> s: <what>" when enabled.
  void operator()(std::string_view what) const;

 private:
  std::string program_;
  std::ostream& err_;
  bool quiet_;
  bool enabled_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ksmc::runtime::cli
