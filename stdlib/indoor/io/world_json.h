// world.json (DESIGN §7): {"map":{...},"units":[...],"doors":[...],"adjacent":[...],"metrics":{...}}
// Keys in this fixed order; numbers printed deterministically (shortest round-trip form).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// Metric names every world.json carries (missing ones are an error in write_world_json).
inline constexpr const char* kRequiredMetrics[] = {"cell_prediction_rate", "iterations", "seconds",
                                                   "iterations_per_second", "log_posterior"};

nlohmann::ordered_json world_to_json(const WorldResult& w);

// Serialised text (2-space indent, trailing newline).
std::string world_json_text(const WorldResult& w);

// Throws std::invalid_argument when a required metric is missing or ids are inconsistent
// (duplicate unit ids, ids <= 0, doors/adjacency naming unknown units), and std::runtime_error
// naming the path when the file cannot be written.
void write_world_json(const std::filesystem::path& path, const WorldResult& w);

// Consistency checks shared by all writers; throws std::invalid_argument.
void validate_world(const WorldResult& w, bool require_metrics);

}  // namespace ksmc::stdlib::indoor::io
