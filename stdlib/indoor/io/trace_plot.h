// trace.png: the log posterior (top) and the acceptance rate (bottom) against the iteration, two
// stacked panels with axes and tick labels (seed Fig. 3.20), drawn with OpenCV.
#pragma once

#include <filesystem>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// "Nice" tick positions (steps of 1, 2 or 5 times a power of ten) covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target_count);

// 1000 x 700 BGR image. Non-finite log posteriors are skipped; an empty trace gives the axes and
// a "no trace samples" note.
cv::Mat3b render_trace(const std::vector<TraceSample>& trace);

void write_trace_png(const std::filesystem::path& path, const std::vector<TraceSample>& trace);

}  // namespace ksmc::stdlib::indoor::io
