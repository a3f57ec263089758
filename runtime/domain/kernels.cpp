#include "runtime/domain/kernels.h"

#include <set>

namespace ksmc::runtime::domain {

mcmc::Schedule make_schedule(const std::vector<mcmc::KernelInfo>& kernels, const std::vector<ScheduleRow>& rows) {
  if (kernels.empty()) throw ConfigError("kernels: the domain declares no kernel");
  std::set<std::string> names;
  for (const auto& k : kernels)
    if (!names.insert(k.name).second) throw ConfigError("kernels: kernel " + k.name + " is declared twice");
  for (const auto& k : kernels)
    if (!names.count(k.reverse)) throw ConfigError("kernels: the reverse " + k.reverse + " of kernel " + k.name + " is not declared");
  if (rows.empty()) throw ConfigError("schedule: the domain has no schedule row");
  std::vector<mcmc::ScheduleRow> out;
  for (const ScheduleRow& r : rows) {
    if (r.begin < 0 || r.end <= r.begin)
      throw ConfigError("schedule: row [" + std::to_string(r.begin) + ", " +
                        (r.end == ScheduleRow::kForever ? std::string("inf") : std::to_string(r.end)) +
                        ") is empty or negative");
    mcmc::ScheduleRow row;
    row.begin = static_cast<std::uint64_t>(r.begin);
    row.end = r.end == ScheduleRow::kForever ? mcmc::kForever : static_cast<std::uint64_t>(r.end);
    row.probabilities = r.probabilities;
    out.push_back(std::move(row));
  }
  try {
    return mcmc::Schedule(kernels, std::move(out));
  } catch (const mcmc::ScheduleError& e) {
    throw ConfigError(std::string("schedule: ") + e.what());
  }
}

}  // namespace ksmc::runtime::domain
