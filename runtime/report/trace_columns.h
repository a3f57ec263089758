// trace.csv (runtime/cli/run_outputs.h) as JSON columns per chain, for the trace plots:
//   {"columns": ["iteration", "log_posterior", ..., "acceptance_ADD", ...],
//    "chains": [{"chain": 0, "iteration": [...], "log_posterior": [...], ...}]}
// Empty cells (a kernel not selected in a window) become null. A chain with more than
// max_rows rows is thinned evenly (first and last rows kept).
#pragma once

#include <cstddef>
#include <string_view>

#include <nlohmann/json.hpp>

namespace ksmc::runtime::report {

// Throws std::invalid_argument "trace.csv:<line>: ..." on a malformed table.
nlohmann::json trace_columns(std::string_view csv, std::size_t max_rows = 2000);

}  // namespace ksmc::runtime::report
