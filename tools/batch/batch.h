// ksmc-batch: one domain binary over many inputs, in parallel on one machine, and a summary
// table (CSV and Markdown) with one row per input. Each run is a pure function from one input
// file to one output folder (OUT/<input stem>/), so the same thing scales out with a Slurm
// job array or GNU parallel (docs/scale.md) without a scheduler of our own.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ksmc::tools::batch {

struct Request {
  std::filesystem::path binary;
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path out;
  unsigned jobs = 1;
  std::vector<std::string> extra;  // passed to every run after the input
};

struct RunRow {
  std::string input;   // as given
  std::string folder;  // OUT/<folder>
  int exit_code = -1;  // 128 + signal when killed; -1 when it could not start
  double seconds = 0.0;
  nlohmann::json summary;  // the run's summary.json (null when absent)
};

// Distinct output folder names from the inputs' stems ("map", "map_2", ...), input order.
std::vector<std::string> folder_names(const std::vector<std::filesystem::path>& inputs);

// Runs every input (at most `jobs` at a time); each run's stdout and stderr go to
// OUT/<folder>.log. Rows in input order.
std::vector<RunRow> run_all(const Request& r);

// The table: fixed columns (input, status, seconds, iterations, it/s, acceptance, best log
// posterior) then every numeric scalar of the runs' summary.json "domain" object (flattened
// with dots, e.g. map.free), in first-seen order.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};
Table make_table(const std::vector<RunRow>& rows);
std::string to_csv(const Table& t);
std::string to_markdown(const Table& t);

}  // namespace ksmc::tools::batch
