// posterior.png (seed Fig. 3.33): the stored posterior samples drawn thin over the map. Each
// sample's unit outlines add to a per-pixel count; a pixel's colour goes from light to dark red
// with the share of samples that put a wall there, so stable walls are dark and lines the
// chain still moves are faint.
// Only real samples are drawn: the kit fills WorldResult::posterior from the samples the run
// stored (--samples N); without samples no posterior.png is written.
#pragma once

#include <filesystem>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// At most this many samples (the last ones) are drawn: the kit reads each back through the
// model's restore(), about 0.1 s per sample on a 2000 x 2300 map.
inline constexpr std::size_t kPosteriorMaxDrawn = 50;

// BGR image, upscaled by overlay_scale(), with a caption band below naming the samples drawn.
// Throws std::invalid_argument when w.posterior is empty.
cv::Mat3b render_posterior(const ClassGrid& grid, const WorldResult& w);

void write_posterior_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
