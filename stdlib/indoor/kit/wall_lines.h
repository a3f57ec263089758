// Walls along a line of a unit's frame, read from the observed grid: the seam test of a merge
// (merged_units.h) and the cuts of a split (split_units.h) after the run.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/geometry.h"

namespace ksmc::stdlib::indoor::kit {

// A segment of frame `f`: x = at for t in [lo, hi] (across_x), else y = at.
struct FrameLine {
  const Frame* f = nullptr;
  bool across_x = true;
  double at = 0.0, lo = 0.0, hi = 0.0;
  Point2 point(double t, double offset = 0.0) const;  // global point at t, `offset` across the line
};

// Samples of `line` every half cell from lo to hi: per sample, whether an occupied cell of
// `observed` lies within `reach` cells across the line. With `thin` > reach, only a wall at
// most about that thick counts: a cell that is not occupied lies on each side, between `reach`
// and `thin` cells from the line (a partition, not a block the line runs through or along).
std::vector<bool> wall_samples(const ClassGrid& observed, const FrameLine& line, int reach, int thin = 0);
// The same samples, or nullopt as soon as more than `max_open` consecutive samples, or more
// than `max_missing` in all, are not wall (the caller would reject the line: it stops early).
std::optional<std::vector<bool>> wall_samples_bounded(const ClassGrid& observed, const FrameLine& line, int reach,
                                                      int thin, std::size_t max_open, std::size_t max_missing);
// The number of samples of `line` (one every half cell from lo to hi).
std::size_t sample_count(const FrameLine& line);

// Share of the samples that are wall (1 when there is no sample).
double wall_share(const std::vector<bool>& samples);

}  // namespace ksmc::stdlib::indoor::kit
