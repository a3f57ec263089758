// Splitting one cluster into stacked boxes. Euclidean clustering merges a box resting on
// another box (and neighbours closer than the tolerance). The top surfaces tell them
// apart: the maximum height per footprint cell (side faces project onto the outline, so
// cell maxima are top heights) forms one plateau per box top. Peeling from the top: the
// points above the next plateau down are the upper box; the rest, without the upper box's
// column, is fitted again. The upper box rests on the rest when the rest's footprint
// covers most of its own, or when the sensor saw through the space below it (a box that
// overhangs the one it rests on: a box standing on the table there would have blocked
// those rays); otherwise it stands on the table (a merged taller neighbour).
#pragma once

#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"
#include "stdlib/tabletop/perception/side_steps.h"
#include "stdlib/tabletop/cloud_likelihood.h"

namespace ksmc::stdlib::tabletop::perception {

struct StackOptions {
  double cell = 0.005;           // m, footprint grid
  double level_gap = 0.02;       // m, plateaus closer in height are one level ...
  double min_level_area = 0.0006; // m^2 of cells at a plateau's height (6 cm^2)
  double peak_contrast = 2.0;    // plateau cells / cells of the bins beside it (tilted faces: 0.75)
  // ... unless a valley lies between them (stop 46): two tops side by side or stacked 10-20 mm
  // apart (a toothpaste beside a medicine box lying on its side, 37 and 26 mm). A plateau next to
  // another one is a peak when one side's bins are clean (peak_contrast x twice that side) and
  // on the other side a bin within two of its centre holds at most `valley_share` of its centre
  // bin (a tilted face fills those bins evenly); a level closer than level_gap to the one above
  // is kept when its centre lies at least `min_valley_bins` bins (of level_gap / 4) below that
  // one's and every bin between holds at most `valley_share` of the smaller centre bin.
  // Off: valley_share < 0.
  double valley_share = 0.1;
  int min_valley_bins = 2;
  double column_margin = 0.006;  // m, the upper box's column is its rectangle grown by this
  double min_support = 0.5;      // share of the upper footprint over the rest that means "stacked"
  // A top whose centre lies over the rest's rectangle, at least `centre_inset` inside it, rests
  // on the rest however little of its footprint that covers: standing on the table there, it
  // would pass through the lower box (a toothpaste lying across a butter box covers 35 % of
  // its footprint with it). Off (negative): the share alone, as before stop 44.
  double centre_inset = 0.01;    // m
  // A top whose side faces stop at the plateau rests on it, when the rays toward the column
  // under the plateau end on the top itself at least as often as on something outside the
  // column (its own shadow; a box in front would hide a standing box's lower faces too). The
  // faces stop when the column holds fewer than `max_points_below` points under the plateau and
  // fewer than `max_below_share` of what its side faces above it (below the top's last
  // `top_band`) would put there. A box lying on a box it hides but for a sliver stood on the
  // table (sim seed 1: a juice box 75 mm tall for 44). Needs the rays (`rays`). Off: 0.
  std::size_t max_points_below = 40;
  double max_below_share = 0.3;
  double top_band = 0.01;        // m
  std::size_t min_points = 40;   // a part with fewer points is dropped
  // Free-space test of "stands on the table" (off: the footprint test alone, as before it
  // existed; it also needs the `rays` argument): the column below the lower plateau, inset by
  // `seen_inset` on every side, may be crossed by at most max(min_seen_through,
  // seen_through_share x the upper box's points) rays.
  bool free_space = true;
  double seen_inset = 0.005;     // m
  std::size_t min_seen_through = 20;
  double seen_through_share = 0.05;
  int max_boxes = 6;
  // Tops above one plateau with a lower surface seen between them (at least `min_lower_cells`
  // cells on the line between them) are peeled as different boxes (top_parts.h); off: as one.
  bool separate_tops = true;
  int min_lower_cells = 2;
  // A resting upper box hides part of the lower one's top; the lower box's side faces under
  // it (below the plateau) stay with the lower box, so its footprint reaches under the upper.
  bool lower_sides = true;
  // Each box found is split again where its side faces step (side_steps.h): a box resting on
  // one of about its footprint shows no plateau of its own.
  SideStepOptions sides;
};

// Boxes of one cluster (table frame), lowest first. Always at least one box. `rays`: the
// whole cloud and the sensor (same frame), for the free-space and own-shadow tests; null
// skips them.
std::vector<UprightBox> fit_stacked_boxes(const Points& points, const BoxFitOptions& box = {},
                                          const StackOptions& options = {}, const RayIndex* rays = nullptr);

}  // namespace ksmc::stdlib::tabletop::perception
