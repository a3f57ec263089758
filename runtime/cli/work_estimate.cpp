#include "runtime/cli/work_estimate.h"

#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "runtime/cli/domain_spec.h"
#include "runtime/cli/stage_log.h"

namespace ksmc::runtime::cli {

std::string format_memory(double mb) {
  return mb >= 1000.0 ? fmt::format("{:.1f} GB", mb / 1000.0) : fmt::format("{:.0f} MB", mb);
}

std::string format_duration(double seconds) {
  if (seconds >= 360000.0) return fmt::format("{:.0f} h", seconds / 3600.0);
  if (seconds >= 5400.0) return fmt::format("{:.1f} h", seconds / 3600.0);
  if (seconds >= 90.0) return fmt::format("{:.0f} min", seconds / 60.0);
  return fmt::format("{:.0f} s", seconds);
}

bool check_work(const WorkEstimate& e, std::uint64_t max_memory_mb, bool quiet, std::ostream& err) {
  if (e.memory_mb > static_cast<double>(max_memory_mb)) {
    throw std::runtime_error(fmt::format("{}: {} needs about {} of memory (estimate), above --max-memory-mb {} (raise it "
                                         "to run anyway)",
                                         e.input, e.what, format_memory(e.memory_mb), max_memory_mb));
  }
  if (e.seconds < kAnnounceSeconds && e.memory_mb < kAnnounceMemoryMb) return false;
  if (!quiet)
    err << fmt::format("{}: {}: about {} and {} of memory (estimate)\n", e.input, e.what, format_duration(e.seconds),
                       format_memory(e.memory_mb))
        << std::flush;
  return true;
}

void check_work(const WorkEstimate& e, const DomainInput& in) {
  const bool large = check_work(e, in.max_memory_mb, in.quiet, std::cerr);
  if ((large || e.seconds >= kStageSeconds) && in.stages != nullptr) in.stages->enable();
}

}  // namespace ksmc::runtime::cli
