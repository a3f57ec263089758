// The segments kit's result files: segments.json (the fitted segments with endpoints and
// support, the Markov logic query marginals, run metrics) and overlay.png (points, segments,
// corners marked; OpenCV).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/mcmc/results.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

nlohmann::json result_json(SegmentsModel& best, const runtime::mcmc::RunResult& run, const std::string& input);
// PNG bytes of the overlay.
std::vector<unsigned char> overlay_png(const SegmentsModel& best, const nlohmann::json& result);

}  // namespace ksmc::stdlib::segments::kit
