#include "runtime/report/trace_columns.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ksmc::runtime::report {

namespace {

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    cells.emplace_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

nlohmann::json cell_value(const std::string& cell, std::size_t line_no) {
  if (cell.empty()) return nullptr;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) {
    throw std::invalid_argument("trace.csv:" + std::to_string(line_no) + ": '" + cell + "' is not a number");
  }
  if (!std::isfinite(v)) return nullptr;  // JSON has no nan / inf
  return v;
}

}  // namespace

nlohmann::json trace_columns(std::string_view csv, std::size_t max_rows) {
  std::vector<std::vector<std::string>> lines;
  std::size_t start = 0;
  while (start < csv.size()) {
    std::size_t end = csv.find('\n', start);
    if (end == std::string_view::npos) end = csv.size();
    std::string_view line = csv.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty()) lines.push_back(split(line));
    start = end + 1;
  }
  if (lines.empty()) throw std::invalid_argument("trace.csv:1: empty table");
  const std::vector<std::string>& header = lines.front();
  if (header.empty() || header.front() != "chain") throw std::invalid_argument("trace.csv:1: first column must be 'chain'");
  // rows per chain, in file order (rows of one chain are contiguous or interleaved)
  std::map<long long, std::vector<std::size_t>> by_chain;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].size() != header.size()) {
      throw std::invalid_argument("trace.csv:" + std::to_string(i + 1) + ": " + std::to_string(lines[i].size()) +
                                  " cells, header has " + std::to_string(header.size()));
    }
    const nlohmann::json c = cell_value(lines[i][0], i + 1);
    if (!c.is_number()) throw std::invalid_argument("trace.csv:" + std::to_string(i + 1) + ": no chain number");
    by_chain[static_cast<long long>(c.get<double>())].push_back(i);
  }
  nlohmann::json columns = nlohmann::json::array();
  for (std::size_t k = 1; k < header.size(); ++k) columns.push_back(header[k]);
  nlohmann::json chains = nlohmann::json::array();
  for (const auto& [chain, rows] : by_chain) {
    std::vector<std::size_t> keep;
    if (rows.size() <= max_rows || max_rows < 2) {
      keep = rows;
    } else {
      for (std::size_t j = 0; j < max_rows; ++j) keep.push_back(rows[j * (rows.size() - 1) / (max_rows - 1)]);
    }
    nlohmann::json c = nlohmann::json::object();
    c["chain"] = chain;
    for (std::size_t k = 1; k < header.size(); ++k) {
      nlohmann::json values = nlohmann::json::array();
      for (const std::size_t r : keep) values.push_back(cell_value(lines[r][k], r + 1));
      c[header[k]] = std::move(values);
    }
    chains.push_back(std::move(c));
  }
  return {{"columns", std::move(columns)}, {"chains", std::move(chains)}};
}

}  // namespace ksmc::runtime::report
