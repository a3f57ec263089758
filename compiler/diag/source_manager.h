// Source files of one compilation: path as given (printed verbatim in diagnostics) and text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ksmc::compiler::diag {

class SourceManager {
 public:
  // Registers a file's text; returns its id (0, 1, ... in registration order).
  int add(std::string path, std::string text);
  [[nodiscard]] const std::string& path(int id) const { return files_.at(static_cast<std::size_t>(id)).path; }
  [[nodiscard]] const std::string& text(int id) const { return files_.at(static_cast<std::size_t>(id)).text; }
  // The text of 1-based line `line` without its line terminator ("" when out of range).
  [[nodiscard]] std::string_view line(int id, int line) const;
  [[nodiscard]] std::size_t size() const { return files_.size(); }

 private:
  struct File {
    std::string path;
    std::string text;
    std::vector<std::size_t> line_starts;
  };
  std::vector<File> files_;
};

}  // namespace ksmc::compiler::diag
