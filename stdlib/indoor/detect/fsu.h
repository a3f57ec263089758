// FSU detector (seed §3.5.2, Fig. 3.13): connected components of the free cells of the map
// that the current world does not explain (C''_M), each turned into an oriented rectangle
// candidate weighted like a WBU unit (eq. 3.10, with a floor so that regions whose walls
// were never observed can still be proposed).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/detect/types.h"
#include "stdlib/indoor/detect/wall_score.h"

namespace ksmc::stdlib::indoor::detect {

struct FsuParams {
  double min_area = 100.0;      // smallest component kept, cells (0.25 m^2)
  int open_radius = 1;          // morphological opening of the unexplained free mask, cells:
                                // removes one-cell slivers along explained borders
  // Rectangle of a component: nullopt -> cv::minAreaRect; a value -> bounding box in the
  // frame of that orientation (degrees, e.g. the map's dominant orientation).
  std::optional<double> frame_deg{};
  double margin = 1.0;          // each side pushed out by this, cells, onto the wall cells
  WallScoreParams wall{};       // for the weight
  double weight_floor = 0.05;   // weight = max(eq. 3.10, floor)
  // A component that fills less than this share of its frame rectangle (a ring of corridors
  // round a courtyard, an L-shaped wing) also gives the largest frame-aligned rectangle inside
  // it, after closing holes of up to 2 x inner_close cells (speckle). Once that piece is
  // explained, a later refresh proposes the next. 0: never; only with frame_deg.
  double inner_below = 0.95;
  int inner_close = 2;
  std::size_t max_candidates = 200;  // largest components first
};

// `explained`: CV_8UC1 of the grid's size, non-zero where the current world explains the
// map (e.g. the rasterised units), or empty for "nothing explained". Candidates are sorted
// by component area, largest first (a component's inner rectangle right after its own).
// Throws std::invalid_argument on bad inputs.
std::vector<UnitCandidate> detect_fsu_units(const ClassGrid& grid, const cv::Mat1b& explained,
                                            const FsuParams& params = {});

}  // namespace ksmc::stdlib::indoor::detect
