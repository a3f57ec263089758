// Dominant wall orientation of a map, modulo 90 degrees, from Hough segments of the
// wall edge cells (wall_edge_mask). Each segment votes with its length into a circular histogram over
// [0, 90) degrees; peaks are refined by the length-weighted circular mean of the
// segments near them.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/hough.h"

namespace ksmc::stdlib::indoor::detect {

struct OrientationParams {
  HoughParams hough{};              // segments of the occupied mask
  double bin_deg = 0.5;             // histogram bin width, degrees
  double smooth_deg = 1.5;          // half-width of the box filter on the histogram, degrees
  double window_deg = 3.0;          // segments within this of a peak refine it and count for it
  double min_secondary = 0.15;      // a further peak needs this fraction of all segment length
  double min_separation_deg = 8.0;  // further peaks at least this far (mod 90) from earlier ones
  std::size_t max_orientations = 3; // dominant one included
};

struct Orientation {
  double angle_deg = 0.0;   // direction of the walls from the x (column) axis, in [0, 90)
  double confidence = 0.0;  // fraction of all segment length within window_deg of the angle
};

struct OrientationAnalysis {
  std::vector<Orientation> peaks;  // strongest first; empty when the map has no segments
  std::vector<Segment> segments;   // the Hough segments used
  double total_length = 0.0;
};

// All strong orientations of `grid`, strongest first. Throws std::invalid_argument on a
// grid that is not a class grid.
OrientationAnalysis analyse_orientations(const ClassGrid& grid, const OrientationParams& params = {});

// The dominant one; angle 0 and confidence 0 when no segment was found.
Orientation dominant_orientation(const ClassGrid& grid, const OrientationParams& params = {});

// Orientations of explicit segments (used by analyse_orientations and by tests).
std::vector<Orientation> orientations_of(const std::vector<Segment>& segments, const OrientationParams& params);

// Smallest difference of two angles modulo 90 degrees, in [0, 45].
double angle_diff_mod90(double a_deg, double b_deg);

}  // namespace ksmc::stdlib::indoor::detect
