// WBU detector (seed §3.5.2, Fig. 3.12): Hough wall segments of the map, expressed in the
// dominant frame (and in further strong orientations), are clustered into wall lines; every line is extended
// across the map, so the lines cut the map into a grid of sub-areas, and each rectangle
// formed by two lines per axis (a union of adjacent sub-areas) is a unit candidate. The
// candidate's weight is eq. 3.10 (its worst wall, eq. 3.11-3.14, computed in the frame
// with prefix sums, so the whole enumeration runs once per map at start-up). Candidates
// that violate the prior (too small, too elongated, weak walls, interior not mostly free)
// are dropped. Rectangle sides lie on the wall centre lines.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/sampler.h"
#include "stdlib/indoor/detect/types.h"

namespace ksmc::stdlib::indoor::detect {

struct WbuParams {
  OrientationParams orientation{};    // Hough segments of the wall edges (orientation.hough,
                                      // run once on the map) and the frames they give
  bool secondary_orientations = true; // also run in further strong orientations
  double axis_tolerance_deg = 2.0;    // segments this close to a frame axis are walls
  double merge_distance = 3.0;        // parallel segments closer than this (cells) form one line
  double min_line_support = 15.0;     // total segment length a line needs, cells (0.75 m)
  std::size_t max_lines_per_axis = 150;  // strongest lines kept per axis and frame
  int wall_tolerance = 2;             // see WallScoreParams::tolerance (0.1 m: SLAM walls drift)
  double min_wall_weight = 0.4;       // every wall of a candidate needs at least this (eq. 3.11)
  double min_side = 10.0;             // shortest unit side, cells (0.5 m)
  double max_side = 1e9;              // longest unit side, cells
  double max_aspect = 25.0;           // longest / shortest side
  double min_free_fraction = 0.5;     // free cells / interior cells (interior: the rectangle
                                      //   shrunk by wall_tolerance + 1 cells on every side)
  double max_occupied_fraction = 0.25;  // occupied cells / interior cells
  std::size_t max_candidates = 20000; // strongest kept (weight, then area, then position)
};

struct WbuResult {
  std::vector<UnitCandidate> candidates;  // sorted: weight descending, then deterministic
  CumulativeSampler sampler;              // over candidates (eq. 3.15-3.17)
  std::vector<double> frames_deg;         // orientations used, dominant first, in (-45, 45]
  std::vector<Segment> wall_lines;        // extended wall lines of all frames, map coordinates
  std::size_t enumerated = 0;             // rectangles that passed all prior tests (before the cap)
};

// Throws std::invalid_argument on a grid that is not a class grid or on inconsistent params.
WbuResult detect_wbu_units(const ClassGrid& grid, const WbuParams& params = {});

}  // namespace ksmc::stdlib::indoor::detect
