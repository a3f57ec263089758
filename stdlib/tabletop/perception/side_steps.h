// Splitting one upright box's points where its side faces step. A box resting on another box
// of about the same footprint hides the lower box's top, so the column has one plateau and
// stack_split sees one box. The side faces still tell the boxes apart: below the interface
// they are the lower box's faces, set back from the upper box's outline or standing out of
// it by the offset and turn at which the two boxes rest. Per face of the top face's outline
// and per height bin, the median signed distance of the side points to that face's line is
// one level per box; a jump between two runs of steady bins is an interface. A single box's
// faces keep one level (a slow drift, from a slightly tilted face, is followed, not cut), and
// occlusion only changes which faces are seen at a height, not their levels.
#pragma once

#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct SideStepOptions {
  bool enabled = true;
  double top_band = 0.008;        // m; the top face's points, and the side points start this far below the top
  std::size_t min_top_points = 20;
  double bin = 0.003;             // m, height bins of the side points
  std::size_t min_bin_points = 8; // a bin with fewer side points is left out
  double max_offset = 0.025;      // m; side points farther from the top's outline belong to something else
  double max_top_level = 0.004;   // m; the top run's level: the top box's faces lie on the top's outline
  double tolerance = 0.002;       // m; a bin this close to its run's level continues the run
  int level_bins = 4;             // a run's level: the median of its last this many bins
  double min_step = 0.003;        // m between the levels of two runs
  int min_run_bins = 3;           // bins of a run on each side of a step (9 mm of face)
  double min_contrast = 5.0;      // step / (MAD of the two runs' bins + noise_floor)
  double noise_floor = 0.0005;    // m
  double min_lower_side = 0.012;  // m; a box under a step with a thinner footprint side is one face, left out
  double edge_band = 0.006;       // m over an interface left out of the upper box's fit (the lower
                                  // box's top edge, seen where the upper box does not cover it)
};

// An interface between two boxes of a column: the upper box's bottom, and the height the
// lower box's side faces reach (the bins between the two are the boxes' edges, left out of
// both fits).
struct SideStep {
  double z = 0.0;
  double lower_top = 0.0;
};

// The interfaces, lowest first, at which the column of `points` (table frame, z up) splits
// into boxes resting on each other; `bottom` is the column's bottom (the table, or the
// plateau it rests on). Empty: one box.
std::vector<SideStep> side_steps(const Points& points, double bottom, const SideStepOptions& options = {},
                                 double footprint_trim = BoxFitOptions{}.footprint_trim);

// The column's boxes, lowest first, split at side_steps: each part is fitted alone, and a
// part above a step has its bottom at the step. `bottom` > 0 sets the lowest part's bottom
// there (a column resting on a plateau); 0 lets the fit find it.
std::vector<UprightBox> fit_column(const Points& points, double bottom, const BoxFitOptions& box,
                                   const SideStepOptions& options);

}  // namespace ksmc::stdlib::tabletop::perception
