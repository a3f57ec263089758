// `--objects A..B` of the simulated-cloud tools: the box count range of a scene.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace ksmc::tools::perception {

// "A..B" -> (A, B); throws std::invalid_argument naming the option otherwise.
inline std::pair<int, int> parse_object_range(const std::string& v) {
  const auto dots = v.find("..");
  if (dots == std::string::npos) throw std::invalid_argument("--objects wants A..B");
  return {std::stoi(v.substr(0, dots)), std::stoi(v.substr(dots + 2))};
}

}  // namespace ksmc::tools::perception
