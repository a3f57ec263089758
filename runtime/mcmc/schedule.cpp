#include "runtime/mcmc/schedule.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace ksmc::runtime::mcmc {

namespace {

std::string range_text(const ScheduleRow& row) {
  return row.end == kForever ? fmt::format("[{}, inf)", row.begin)
                             : fmt::format("[{}, {})", row.begin, row.end);
}

}  // namespace

Schedule::Schedule(std::vector<KernelInfo> kernels, std::vector<ScheduleRow> rows)
    : kernels_(std::move(kernels)), source_rows_(std::move(rows)) {
  if (kernels_.empty()) throw ScheduleError("schedule: no kernels");
  std::map<std::string, std::size_t> index;
  for (std::size_t k = 0; k < kernels_.size(); ++k) {
    if (kernels_[k].name.empty()) throw ScheduleError("schedule: kernel with an empty name");
    if (!index.emplace(kernels_[k].name, k).second) {
      throw ScheduleError(fmt::format("schedule: kernel '{}' declared twice", kernels_[k].name));
    }
  }
  reverse_.resize(kernels_.size());
  for (std::size_t k = 0; k < kernels_.size(); ++k) {
    const auto it = index.find(kernels_[k].reverse);
    if (it == index.end()) {
      throw ScheduleError(fmt::format("schedule: kernel '{}' names reverse '{}', which is not a kernel",
                                      kernels_[k].name, kernels_[k].reverse));
    }
    reverse_[k] = it->second;
  }
  for (std::size_t k = 0; k < kernels_.size(); ++k) {
    if (reverse_[reverse_[k]] != k) {
      throw ScheduleError(fmt::format(
          "schedule: kernel '{}' has reverse '{}', whose reverse is '{}' (pairs must match)",
          kernels_[k].name, kernels_[reverse_[k]].name, kernels_[reverse_[k]].reverse));
    }
  }

  if (source_rows_.empty()) throw ScheduleError("schedule: no rows");
  for (std::size_t r = 0; r < source_rows_.size(); ++r) {
    const ScheduleRow& src = source_rows_[r];
    const std::string where = fmt::format("schedule row {} {}", r + 1, range_text(src));
    const std::uint64_t expected_begin = r == 0 ? 0 : source_rows_[r - 1].end;
    if (src.begin != expected_begin) {
      throw ScheduleError(r == 0 ? fmt::format("{}: the first row must start at iteration 0", where)
                                 : fmt::format("{}: rows must be contiguous, expected it to start at {}",
                                               where, expected_begin));
    }
    if (src.end <= src.begin) throw ScheduleError(fmt::format("{}: empty iteration range", where));
    if (r + 1 == source_rows_.size() && src.end != kForever) {
      throw ScheduleError(fmt::format("{}: the last row must be open-ended (end = inf)", where));
    }
    Row row{src.begin, src.end, std::vector<double>(kernels_.size(), 0.0),
            std::vector<double>(kernels_.size(), 0.0), {}};
    std::vector<bool> seen(kernels_.size(), false);
    double sum = 0.0;
    for (const auto& [name, p] : src.probabilities) {
      const auto it = index.find(name);
      if (it == index.end()) throw ScheduleError(fmt::format("{}: unknown kernel '{}'", where, name));
      if (seen[it->second]) throw ScheduleError(fmt::format("{}: kernel '{}' listed twice", where, name));
      seen[it->second] = true;
      if (!std::isfinite(p) || p < 0.0 || p > 1.0) {
        throw ScheduleError(fmt::format("{}: probability of '{}' is {}, not in [0, 1]", where, name, p));
      }
      row.prob[it->second] = p;
      sum += p;
    }
    if (std::fabs(sum - 1.0) > 1e-9) {
      throw ScheduleError(fmt::format("{}: probabilities sum to {}, not 1", where, sum));
    }
    for (std::size_t k = 0; k < kernels_.size(); ++k) {
      if (row.prob[k] > 0.0 && row.prob[reverse_[k]] <= 0.0) {
        throw ScheduleError(fmt::format(
            "{}: kernel '{}' has probability {} but its reverse '{}' has 0 (moves could not be undone)",
            where, kernels_[k].name, row.prob[k], kernels_[reverse_[k]].name));
      }
      row.log_sel_ratio[k] =
          row.prob[k] > 0.0 ? std::log(row.prob[reverse_[k]]) - std::log(row.prob[k]) : 0.0;
    }
    row.alias = AliasTable(row.prob);
    rows_.push_back(std::move(row));
  }
}

Schedule Schedule::constant(std::vector<KernelInfo> kernels,
                            std::vector<std::pair<std::string, double>> probabilities) {
  return Schedule(std::move(kernels), {ScheduleRow{0, kForever, std::move(probabilities)}});
}

std::size_t Schedule::row_index(std::uint64_t iteration) const noexcept {
  const auto it = std::upper_bound(rows_.begin(), rows_.end(), iteration,
                                   [](std::uint64_t i, const Row& row) { return i < row.end; });
  return it == rows_.end() ? rows_.size() - 1 : static_cast<std::size_t>(it - rows_.begin());
}

}  // namespace ksmc::runtime::mcmc
