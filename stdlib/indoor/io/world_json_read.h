// Reading world.json back (results of earlier runs, ground-truth files such as
// examples/indoor/sim_office_truth.json) into a WorldResult, for evaluation and re-rendering.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// Thrown for unreadable files, JSON syntax errors (with the line) and schema errors (with the
// JSON path, e.g. "units[3].corners[2]"). what() starts with "<file>[:line]: error: ".
class WorldJsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `metrics` and `adjacent` may be absent (truth files); everything else of DESIGN §7 is required.
// Unit/door/adjacency consistency is checked like the writers do. The trace is left empty.
WorldResult read_world_json(const std::filesystem::path& path);
WorldResult parse_world_json(const std::string& text, const std::string& name);

}  // namespace ksmc::stdlib::indoor::io
