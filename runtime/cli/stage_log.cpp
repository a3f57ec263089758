#include "runtime/cli/stage_log.h"

#include <utility>

#include <fmt/format.h>

#include "runtime/cli/domain_spec.h"

namespace ksmc::runtime::cli {

StageLog::StageLog(std::string program, std::ostream& err, bool quiet)
    : program_(std::move(program)), err_(err), quiet_(quiet), start_(std::chrono::steady_clock::now()) {}

void StageLog::operator()(std::string_view what) const {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  err_ << fmt::format("{}: {:.1f} s: {}\n", program_, s, what) << std::flush;
}

void stage(const DomainInput& in, std::string_view what) {
  if (in.stages != nullptr) (*in.stages)(what);
}

}  // namespace ksmc::runtime::cli
