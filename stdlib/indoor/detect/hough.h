// Probabilistic Hough line segments (cv::HoughLinesP) on a binary mask, in cell units.
// OpenCV seeds its internal RNG identically on every call, so results are deterministic.
#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

struct HoughParams {
  double rho = 1.0;           // distance resolution, cells
  double theta_deg = 0.5;     // angle resolution, degrees
  int threshold = 20;         // accumulator votes needed for a line
  double min_length = 15.0;   // shortest segment kept, cells (0.75 m at 0.05 m/cell)
  double max_gap = 3.0;       // largest gap bridged inside a segment, cells (0.15 m)
};

// Segments of the non-zero pixels of `mask` (CV_8UC1). Throws std::invalid_argument on a
// mask of another type or on non-positive resolutions.
std::vector<Segment> hough_segments(const cv::Mat1b& mask, const HoughParams& params);

// Mask (255/0) of the cells of `grid` equal to `value` (a Cell).
cv::Mat1b class_mask(const cv::Mat1b& grid, unsigned char value);

// Wall edge mask (255/0): occupied cells with a non-occupied cell among their 8 neighbours
// (outside the map counts as occupied). This is what the Hough transform sees: thick or
// filled occupied regions (e.g. maps whose unknown space is classified occupied) only
// contribute their boundary.
cv::Mat1b wall_edge_mask(const cv::Mat1b& grid);

// Throws std::invalid_argument naming `who` unless `grid` is a non-empty CV_8UC1 class grid
// whose values are all Cell::Free/Unknown/Occupied.
void check_class_grid(const cv::Mat1b& grid, const char* who);

}  // namespace ksmc::stdlib::indoor::detect
