// The segments kit's result files: segments.json (the fitted segments with endpoints and
// support, their unary query marginals, the pairs of binary relations, "queries" — every
// ground query atom's marginal, runtime::domain::Semantics::queries_json — and run metrics)
// and overlay.png (points, segments, the meeting points of pairs in a binary query relation,
// one colour per predicate; OpenCV).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/mcmc/results.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

nlohmann::ordered_json result_json(SegmentsModel& best, const runtime::mcmc::RunResult& run, const std::string& input);
// PNG bytes of the overlay.
std::vector<unsigned char> overlay_png(const SegmentsModel& best, const nlohmann::ordered_json& result);

}  // namespace ksmc::stdlib::segments::kit
