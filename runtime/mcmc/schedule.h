// Kernel schedules: the probability Phi of selecting each sub-kernel, by iteration range
// (dissertation Table 3.2: rows [0,1000), [1000,4000), [4000,inf)).
//
// Validated on construction (ScheduleError with a message naming the row and kernel):
// at least one row; rows contiguous from 0 with the last one open-ended; each row's
// probabilities finite, in [0,1], summing to 1 (within 1e-9); every named kernel known;
// every kernel pair consistent (reverse of reverse is itself, the reverse exists); and
// a kernel with Phi > 0 in a row has a reverse with Phi > 0 in that row, since the
// acceptance ratio needs Phi(reverse) / Phi(kernel).
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "runtime/mcmc/alias_table.h"
#include "runtime/mcmc/rng.h"

namespace ksmc::runtime::mcmc {

class ScheduleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint64_t kForever = std::numeric_limits<std::uint64_t>::max();

struct KernelInfo {
  std::string name;
  std::string reverse;
};

struct ScheduleRow {
  std::uint64_t begin = 0;
  std::uint64_t end = kForever;  // exclusive; kForever = infinity
  std::vector<std::pair<std::string, double>> probabilities;  // by kernel name; absent = 0
};

class Schedule {
 public:
  Schedule() = default;
  // kernels: the kernel table in engine order; rows as above. Throws ScheduleError.
  Schedule(std::vector<KernelInfo> kernels, std::vector<ScheduleRow> rows);

  // One row for all iterations.
  static Schedule constant(std::vector<KernelInfo> kernels,
                           std::vector<std::pair<std::string, double>> probabilities);

  std::size_t kernel_count() const noexcept { return kernels_.size(); }
  const std::vector<KernelInfo>& kernels() const noexcept { return kernels_; }
  std::size_t row_count() const noexcept { return rows_.size(); }
  const ScheduleRow& row(std::size_t r) const { return source_rows_.at(r); }

  // Index of the row containing `iteration` (O(log rows)).
  std::size_t row_index(std::uint64_t iteration) const noexcept;
  std::uint64_t row_end(std::size_t r) const noexcept { return rows_[r].end; }

  // Kernel index drawn from row r (O(1), alias table).
  std::size_t pick(std::size_t r, Rng& rng) const noexcept { return rows_[r].alias.sample(rng); }
  double probability(std::size_t r, std::size_t kernel) const noexcept {
    return rows_[r].prob[kernel];
  }
  // log Phi(reverse(k)) - log Phi(k) in row r: the selection term of the MH ratio.
  double log_selection_ratio(std::size_t r, std::size_t kernel) const noexcept {
    return rows_[r].log_sel_ratio[kernel];
  }
  std::size_t reverse_of(std::size_t kernel) const noexcept { return reverse_[kernel]; }

 private:
  struct Row {
    std::uint64_t begin;
    std::uint64_t end;
    std::vector<double> prob;           // per kernel
    std::vector<double> log_sel_ratio;  // per kernel
    AliasTable alias;
  };
  std::vector<KernelInfo> kernels_;
  std::vector<std::size_t> reverse_;
  std::vector<Row> rows_;
  std::vector<ScheduleRow> source_rows_;
};

}  // namespace ksmc::runtime::mcmc
